#!/usr/bin/env bash
# Fuzzes the problem-file reader, the expression evaluator, the Gmsh reader and meshes from
# arrays with libFuzzer, under AddressSanitizer and UndefinedBehaviorSanitizer, for a bounded
# time per target.
#   tests/fuzz/run.sh [SECONDS_PER_TARGET] [TARGET...]     (default 60 s; targets: problem_file,
#                                          expression, gmsh_reader, mesh_arrays; default all)
# Needs clang (Debian: apt-get install clang, done here when run as root); the normal build and CI
# do not. The targets are compiled straight from the io sources into $SIGNORINI_FUZZ_BUILD
# (default build/fuzz). Seeds are tests/fuzz/corpus/<target>/ (read only); what the fuzzer
# finds goes to $SIGNORINI_FUZZ_BUILD/corpus/<target>/, crashes to .../artifacts/<target>/.
# Exit status: 0 nothing found, 1 a target crashed (the input is named), 2 cannot build.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(problem_file expression gmsh_reader mesh_arrays)
build="${SIGNORINI_FUZZ_BUILD:-build/fuzz}"

if ! command -v clang++ >/dev/null 2>&1; then
  if [ "$(id -u)" -eq 0 ]; then
    echo "fuzz: installing clang"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends clang
  else
    echo "fuzz: clang++ is missing (Debian: apt-get install clang)" >&2
    exit 2
  fi
fi

flags=(-std=c++20 -O1 -g -fno-omit-frame-pointer
       -DTOML_HEADER_ONLY=1  # toml++ compiled here, so that its parser is instrumented too
       # ... but with its assertions off, as in the library the tool links (Debian's, built with
       # NDEBUG): toml++ 3.3.0 asserts in parse_key() on input its caller lets through ("[[" and a
       # line break), which it then reports as a syntax error (tests/input/problem_file_test.cpp).
       "-DTOML_ASSERT(expr)=((void)0)"
       -DEIGEN_SPARSEMATRIX_PLUGIN='"signorini/core/eigen_sparse_move.hpp"'
       -Iinclude -I"$build/include" -Isrc -I/usr/include/eigen3 -I/usr/include/suitesparse)
# Every UBSan check but "unreachable": toml++ 3.3.0 reaches __builtin_unreachable() in
# is_non_ascii_horizontal_whitespace() for code points U+00A1-U+0499 and U+FB07-U+FEFE where it
# tests for whitespace (marzer/tomlplusplus#190, #295; fixed upstream by #305, after 3.4.0). g++
# and clang both compile it to "not whitespace", which is right, and tests/input/problem_file_test.cpp
# checks the outcome; the check would otherwise stop every run at the first such character.
sanitizers=(-fsanitize=address,undefined -fno-sanitize=unreachable -fno-sanitize-recover=undefined)
# What the targets exercise, instrumented for coverage: the input, output and mesh modules and the
# validate() functions of the options. The rest of the library is only linked (linear_solver.cpp also makes
# the solvers), so it goes uninstrumented into an archive, from which the link takes what it needs.
instrumented=(
  src/signorini/input/*.cpp src/signorini/output/*.cpp src/signorini/mesh/*.cpp
  src/signorini/fem/material.cpp
  src/signorini/contact/contact_solver_options.cpp src/signorini/linalg/linear_solver.cpp
)
libraries=(-lcholmod -lumfpack -lsuitesparseconfig -lmuparser -lfmt -lopenblas)

# Objects built with other flags (an earlier version of this script) are built again.
if [ "$(cat "$build/flags" 2>/dev/null)" != "${flags[*]} ${sanitizers[*]}" ]; then
  rm -rf "$build/obj" "$build/rest"
fi
mkdir -p "$build/obj" "$build/rest" "$build/include/signorini"
# The library's generated header (src/CMakeLists.txt makes it from cmake/config.hpp.in), without
# CUDA: the fuzz build has no GPU backend.
sed -e 's/@PROJECT_VERSION@/fuzz/' -e 's/@PROJECT_VERSION_[A-Z]*@/0/' \
    -e 's|#cmakedefine SIGNORINI_HAVE_CUDA 1|/* no CUDA */|' cmake/config.hpp.in \
    > "$build/include/signorini/config.hpp.new"
cmp -s "$build/include/signorini/config.hpp.new" "$build/include/signorini/config.hpp" ||
  mv "$build/include/signorini/config.hpp.new" "$build/include/signorini/config.hpp"
echo "${flags[*]} ${sanitizers[*]}" > "$build/flags"
# A source is compiled again when it, or any header of the library, is newer than its object.
newest_header=$(find src/signorini -name '*.hpp' -printf '%T@ %p\n' | sort -n | tail -1 | cut -d' ' -f2)
compile() {  # source object extra-flags...
  local src="$1" obj="$2"
  shift 2
  if [ ! -f "$obj" ] || [ "$src" -nt "$obj" ] || [ "$newest_header" -nt "$obj" ]; then
    echo "fuzz: compiling $src"
    clang++ "${flags[@]}" "$@" -c "$src" -o "$obj"
  fi
}
objects=()
for src in "${instrumented[@]}"; do
  obj="$build/obj/$(basename "${src%.cpp}").o"
  compile "$src" "$obj" "${sanitizers[@]}" -fsanitize=fuzzer-no-link || exit 2
  objects+=("$obj")
done
rest=()
for src in src/signorini/*/*.cpp src/signorini/*/detail/*.cpp; do
  case " ${instrumented[*]} " in *" $src "*) continue ;; esac
  case "$src" in src/signorini/petsc/*) continue ;; esac  # (a library of its own, with PETSc)
  obj="$build/rest/$(basename "${src%.cpp}").o"
  compile "$src" "$obj" || exit 2
  rest+=("$obj")
done
rm -f "$build/rest.a"
ar rcs "$build/rest.a" "${rest[@]}"

found=0
for target in "${targets[@]}"; do
  src="tests/fuzz/${target}_fuzzer.cpp"
  [ -f "$src" ] || { echo "fuzz: no target '$target' ($src)" >&2; exit 2; }
  compile "$src" "$build/obj/${target}_fuzzer.o" "${sanitizers[@]}" -fsanitize=fuzzer-no-link \
    || exit 2
  exe="$build/${target}_fuzzer"
  clang++ "${flags[@]}" "${sanitizers[@]}" -fsanitize=fuzzer "$build/obj/${target}_fuzzer.o" \
    "${objects[@]}" "$build/rest.a" "${libraries[@]}" -o "$exe" || exit 2
  mkdir -p "$build/corpus/$target" "$build/artifacts/$target"
  echo "fuzz: $target for $seconds s"
  # (Gmsh files are longer than a problem file; the seeds run to a few kilobytes.)
  max_len=4096
  [ "$target" = gmsh_reader ] && max_len=16384
  dict=()
  [ -f "tests/fuzz/$target.dict" ] && dict=(-dict="tests/fuzz/$target.dict")
  mkdir -p "tests/fuzz/corpus/$target"
  # New inputs go to the first corpus folder (the build's); the seeds in the repository are read.
  if ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 "$exe" \
      -max_total_time="$seconds" -max_len="$max_len" -timeout=10 -rss_limit_mb=4096 \
      -print_final_stats=1 "${dict[@]}" -artifact_prefix="$build/artifacts/$target/" \
      "$build/corpus/$target" "tests/fuzz/corpus/$target" 2>"$build/$target.log"; then
    tail -n 12 "$build/$target.log" | grep -E '^(#|stat::|Done)' || true
    echo "fuzz: $target: nothing found"
  else
    found=1
    grep -E 'ERROR|SUMMARY|Test unit written|fuzzer:' "$build/$target.log" | head -20 || true
    echo "fuzz: $target CRASHED; full log $build/$target.log; reproduce with $exe <artifact>" >&2
  fi
done
exit $found
