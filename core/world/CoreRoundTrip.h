// How long a write on one CPU takes to be seen on another and answered: two threads, each pinned to one of the first
// two CPUs this thread may run on, pass a counter back and forth. On a shared virtual machine this time depends on
// where the host runs the virtual CPUs, which the machine cannot see: on this project's two-core machine it was 50-64
// ns for minutes at a time, then 310-400 ns for tens of seconds, and the two-thread bench of ramps.obj went from a
// median 1.88x as fast as one thread to 1.45x (tests/benchmarks/LOG.md, 2026-12-04). A step on a team meets at barriers
// and hands bodies from core to core, so a benchmark that compares thread counts reports this time beside its figures.
#pragma once

#include <optional>

namespace rl {

// The median round trip over `rounds` batches of `tripsPerRound` trips, in nanoseconds; nothing if this thread may run
// on fewer than two CPUs, a thread cannot be started or pinned, or the trips take more than about a second in all (the
// other CPU was taken away). Linux only; elsewhere, nothing.
std::optional<double> measureCoreRoundTripNs(int rounds = 5, int tripsPerRound = 2000);

} // namespace rl
