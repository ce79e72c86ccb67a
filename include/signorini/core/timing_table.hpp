#pragma once
// Wall-clock seconds per named phase, in the order the phases first ran (as deal.II's
// TimerOutput table): users see where the time goes.

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace signorini {

class TimingTable {
 public:
  /// Adds seconds to a phase (created on first use, keeping first-use order).
  void add(const std::string& phase, double seconds);
  /// Seconds of a phase; 0 if it never ran.
  [[nodiscard]] double seconds(const std::string& phase) const;
  [[nodiscard]] double total() const;
  [[nodiscard]] const std::vector<std::pair<std::string, double>>& phases() const {
    return phases_;
  }
  /// Adds every phase of another table.
  void merge(const TimingTable& other);

 private:
  std::vector<std::pair<std::string, double>> phases_;
};

/// Adds the time between construction and destruction (or stop()) to a phase.
class ScopedTimer {
 public:
  ScopedTimer(TimingTable& table, std::string phase)
      : table_(&table), phase_(std::move(phase)), start_(std::chrono::steady_clock::now()) {}
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;
  ~ScopedTimer() { stop(); }
  void stop() {
    if (table_ == nullptr) return;
    const std::chrono::duration<double> dt = std::chrono::steady_clock::now() - start_;
    table_->add(phase_, dt.count());
    table_ = nullptr;
  }

 private:
  TimingTable* table_;
  std::string phase_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace signorini
