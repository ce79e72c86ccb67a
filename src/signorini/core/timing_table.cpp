#include "signorini/core/timing_table.hpp"

namespace signorini {

void TimingTable::add(const std::string& phase, double seconds) {
  for (auto& [name, s] : phases_) {
    if (name == phase) {
      s += seconds;
      return;
    }
  }
  phases_.emplace_back(phase, seconds);
}

double TimingTable::seconds(const std::string& phase) const {
  for (const auto& [name, s] : phases_)
    if (name == phase) return s;
  return 0.0;
}

double TimingTable::total() const {
  double t = 0.0;
  for (const auto& [name, s] : phases_) t += s;
  return t;
}

void TimingTable::merge(const TimingTable& other) {
  for (const auto& [name, s] : other.phases_) add(name, s);
}

}  // namespace signorini
