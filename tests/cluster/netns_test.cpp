// Multi-host runs on one machine: scripts/cluster/netns.sh puts each rank in its own network
// namespace (127.200.0.0/24, TCP only) and the render matches the single-host image.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "image/image.h"
#include "test_support.h"

using namespace relt;
using namespace relt::test;

TEST(Cluster, TwoNamespaceHostsGiveTheSingleHostImage) {
  if (::geteuid() != 0) GTEST_SKIP() << "network namespaces need root";
  const std::string probe = "relt-probe-" + std::to_string(::getpid());
  const CommandResult p = runCommand("ip netns add " + probe + " && ip netns del " + probe);
  if (p.exitCode != 0) GTEST_SKIP() << "network namespaces are not available here: " << p.output;

  const std::string dir = makeTempDir("cluster");
  const std::string args = " render " + sourcePath("scenes/cornell-box.gltf") +
                           " --integrator relt --mutations-per-pixel 8 --ladders 3 --width 40 --height 30 --seed 5";
  const CommandResult one = runCommand(mpirun(1) + reltBinary() + args + " -o " + dir + "/one.exr");
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const CommandResult two = runCommand(sourcePath("scripts/cluster/netns.sh") + " 2 " + reltBinary() + args + " -o " +
                                       dir + "/two.exr --stats " + dir + "/two.json");
  ASSERT_EQ(two.exitCode, 0) << two.output;
  std::ifstream stats(dir + "/two.json");
  const nlohmann::json j = nlohmann::json::parse(stats);
  ASSERT_EQ(j["hosts"].size(), 2u);
  EXPECT_NE(j["hosts"][0], j["hosts"][1]) << "each rank on its own host";
  expectSameImage(readExr(dir + "/one.exr"), readExr(dir + "/two.exr"));
  EXPECT_TRUE(runCommand("ip netns list | grep -q relt").exitCode != 0) << "namespaces torn down";
}
