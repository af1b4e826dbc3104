#include "test_support.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace relt::test {

std::string sourcePath(const std::string& relative) { return std::string(RELT_SOURCE_DIR) + "/" + relative; }
std::string reltBinary() { return RELT_BIN; }

CommandResult runCommand(const std::string& command) {
  CommandResult r;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
  const int status = ::pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

SignalledRun runAndSignal(const std::string& command, const std::string& log, const std::string& signal,
                          const std::string& victim, const std::string& progress) {
  const std::string target = victim.empty() ? "$pid" : "$(pgrep -f -n '" + victim + "')";
  const std::string script = "(" + command + ") > " + log + " 2>&1 & pid=$!; " +
                             "for i in $(seq 300); do grep -qE '" + progress + "' " + log + " && break; sleep 0.05; done; " +
                             "kill -" + signal + " " + target + "; t0=$(date +%s.%N); wait $pid; rc=$?; " +
                             "echo \"seconds $(echo \"$(date +%s.%N) - $t0\" | bc)\"; cat " + log + "; exit $rc";
  SignalledRun out;
  out.result = runCommand(script);
  const size_t at = out.result.output.find("seconds ");
  if (at != std::string::npos) out.secondsAfterSignal = std::stod(out.result.output.substr(at + 8));
  return out;
}

std::string mpirun(int ranks) {
  return "mpirun --allow-run-as-root --oversubscribe --mca pml ob1 --mca btl self,vader -np " + std::to_string(ranks) + " ";
}

std::string makeTempDir(const std::string& tag) {
  static std::atomic<int> counter{0};
  const auto dir = std::filesystem::temp_directory_path() /
                   ("relt-test-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

bool fileExists(const std::string& path) { return std::filesystem::exists(path); }

void expectSameImage(const Image& a, const Image& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  double maxRel = 0.0;
  for (size_t i = 0; i < a.rgb.size(); ++i) {
    const double scale = std::max({std::abs(double(a.rgb[i])), std::abs(double(b.rgb[i])), 1e-6});
    maxRel = std::max(maxRel, std::abs(double(a.rgb[i]) - double(b.rgb[i])) / scale);
  }
  EXPECT_LE(maxRel, 1e-5);
  EXPECT_GT(a.mean(), 0.0);
}

}  // namespace relt::test
