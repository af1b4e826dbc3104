#pragma once
// Shared helpers for relt's tests.
#include <string>

#include "image/image.h"

namespace relt::test {

// Absolute path of a file in the source tree, e.g. sourcePath("scenes/cornell-box.gltf").
std::string sourcePath(const std::string& relative);
// The relt executable built alongside the tests.
std::string reltBinary();

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};
// Runs a shell command, capturing its output and exit code.
CommandResult runCommand(const std::string& command);
// Runs `command` in the background (its output to `log`), waits for its first progress line
// matching the extended regular expression `progress` (at most 15 s; by default one of the chains
// or passes, not of the direct-emission pass before them), sends `signal` (e.g. "TERM") to the
// process whose command line matches the pgrep pattern `victim` (empty: the command itself) and
// waits for the end. The result's output is the log; `secondsAfterSignal` runs from the signal.
struct SignalledRun {
  CommandResult result;
  double secondsAfterSignal = 0.0;
};
constexpr const char* kRenderProgress = "^ *[0-9.]+%.* elapsed";
constexpr const char* kDirectPassProgress = "^direct emission .* elapsed";
SignalledRun runAndSignal(const std::string& command, const std::string& log, const std::string& signal,
                          const std::string& victim = "", const std::string& progress = kRenderProgress);
// mpirun with the options this machine needs (root, oversubscription, no slow transports).
std::string mpirun(int ranks);

// A fresh empty directory under the system temp dir, unique per call.
std::string makeTempDir(const std::string& tag);
bool fileExists(const std::string& path);

// Two renders of the same samples (e.g. on different rank counts) agree up to the order of
// floating-point sums: every pixel within 1e-5 relative; the image is not black.
void expectSameImage(const Image& a, const Image& b);

}  // namespace relt::test
