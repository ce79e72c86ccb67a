#pragma once
// Peak resident memory of this process, resettable so that a benchmark can measure one case at a
// time (Linux: VmHWM in /proc/self/status, reset by writing 5 to /proc/self/clear_refs), and the
// physical and the available memory of the machine.

namespace signorini {

/// Peak resident set size in bytes since the last reset (or the start); 0 if unknown.
double peak_resident_bytes();
/// Starts a new peak measurement from the current resident size. Returns false where the system
/// cannot reset it (the peak then covers the whole run so far).
bool reset_peak_resident();
/// Physical memory of this machine in bytes, or 0 if unknown.
double physical_memory_bytes();
/// Memory the system could give this process now without swapping (Linux: MemAvailable in
/// /proc/meminfo), in bytes, or 0 if unknown.
double available_memory_bytes();

}  // namespace signorini
