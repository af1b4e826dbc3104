#pragma once
// The pass loop of the per-pixel integrators (pt, bdpt, erpt): pass k renders the work units
// (k, row) this rank owns; --spp N runs N passes, --time decides collectively after each pass.
#include <functional>
#include <string>

#include "comm.h"
#include "render/settings.h"

namespace relt::mpi {

// Calls renderUnit(pass, row) for every owned unit of every pass and returns the number of passes.
// If rate is given, the root prints a progress line at most once a second with rate(elapsed)
// samples per second. If snapshot is given and --snapshot-every is set, every rank calls
// snapshot(passes so far) after the same passes (the elapsed time is agreed every pass).
// A render resumed from a checkpoint starts after `start.passes` passes and `start.elapsed`
// seconds; passDone(passes, elapsed, more, save), if given, runs on every rank after every pass
// (the last one with more = false: the budget is spent or a rank was signalled to stop; save: a
// rank was asked to save, see interrupt.h, and the snapshot was written: checkpoint now).
struct PassStart {
  int passes = 0;
  double elapsed = 0.0;
};
int runPasses(const Session& session, const RenderSettings& settings,
              const std::function<void(uint64_t pass, int row)>& renderUnit,
              const std::function<double(double elapsed)>& rate = {},
              const std::function<void(int passes)>& snapshot = {}, const PassStart& start = {},
              const std::function<void(int passes, double elapsed, bool more, bool save)>& passDone = {});

}  // namespace relt::mpi
