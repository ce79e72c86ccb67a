#pragma once
// `signorini bench --device cuda` (docs/gpu.md): the table that puts each GPU row beside the CPU
// reference of the same run and the paper's Table 1, and the choice of the largest mesh that fits
// on the GPU.

#include <string>
#include <vector>

#include "signorini/benchmark/paper_benchmark_suite.hpp"

namespace signorini::app {

/// One line per GPU row: contact-solve seconds on the GPU and of the CPU reference
/// ("uzawa_gnm/cholmod+schur" on the same mesh), their ratio, the paper's CPU and GPU seconds,
/// the relative difference of M(u*, l*), CG iterations and GPU memory; under it the same
/// algorithm on the CPU backend where the run has it.
std::string gpu_comparison_table(const std::vector<BenchmarkRow>& rows);

/// Unknowns of the paper's mesh nx x nx/3 (two per node).
double paper_mesh_unknowns(Index nx);

/// The largest nx (a multiple of 480, so that the multigrid hierarchy reaches 15 x 5) whose
/// memory at `bytes_per_unknown` fits in 85 % of `gpu_bytes`, and whose stiffness stays below the
/// 2^31 nonzeros of 32-bit cuSPARSE indices (at most 18 per row for Q1 in 2D). At least 480.
Index largest_paper_mesh_nx(double bytes_per_unknown, double gpu_bytes);

}  // namespace signorini::app
