// The pieces behind a run's budgets, without processes: the memory limits a
// cgroup sets (v1 and v2, from a cgroup tree made here), and the memory
// estimate's parts as a run's shape changes.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "sw/run/machine_memory.h"
#include "sw/run/run_footprint.h"

namespace cdvp {
namespace {

namespace fs = std::filesystem;

class CgroupTree : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("cdvp-cgroup-" + std::to_string(::getpid()) + "-" +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root_);
    }
    void TearDown() override { fs::remove_all(root_); }
    void put(const std::string& relative, const std::string& text) {
        fs::create_directories((root_ / relative).parent_path());
        std::ofstream(root_ / relative) << text << '\n';
    }
    uint64_t limit(const std::string& proc_self_cgroup) const {
        return cgroup_memory_limit(proc_self_cgroup, root_.string());
    }
    fs::path root_;
};

TEST_F(CgroupTree, V2TakesTheLeastLimitOfTheCgroupAndItsAncestors) {
    put("a/b/memory.max", "max");
    put("a/memory.max", "1073741824");
    EXPECT_EQ(limit("0::/a/b\n"), uint64_t{1} << 30);
    put("a/b/memory.max", "536870912");
    EXPECT_EQ(limit("0::/a/b\n"), uint64_t{1} << 29);
}

TEST_F(CgroupTree, V1ReadsTheMemoryControllersHierarchy) {
    // A v1 cgroup without a limit reads about 2^63; a container sees its own
    // cgroup at the hierarchy's root, whatever path /proc/self/cgroup names.
    put("memory/memory.limit_in_bytes", "2147483648");
    put("memory/x/memory.limit_in_bytes", "9223372036854771712");
    EXPECT_EQ(limit("9:name=systemd:/\n4:memory:/x\n1:cpu:/\n"), uint64_t{2} << 30);
    EXPECT_EQ(limit("4:cpuacct,memory:/not/mounted/here\n"), uint64_t{2} << 30);
}

TEST_F(CgroupTree, NoLimitAnywhereIsNone) {
    put("memory.max", "max");
    EXPECT_EQ(limit("0::/\n"), 0u);
    EXPECT_EQ(limit("garbage\n\n4:memory\n"), 0u);
    EXPECT_EQ(limit(""), 0u);
}

TEST(MachineMemory, TheLeastLimitDecidesAndIsNamed) {
    MachineMemory m{uint64_t{24} << 30, 0, 0};
    EXPECT_EQ(m.least(), uint64_t{24} << 30);
    EXPECT_EQ(m.describe_least(), "this machine's 24576 MiB of memory");
    m.cgroup = uint64_t{2} << 30;
    EXPECT_EQ(m.describe_least(), "the cgroup's memory limit of 2048 MiB");
    m.address_space = uint64_t{1} << 30;
    EXPECT_EQ(m.least(), uint64_t{1} << 30);
    EXPECT_EQ(m.describe_least(), "RLIMIT_AS of 1024 MiB");
    const MachineMemory here = machine_memory();
    EXPECT_GT(here.physical, uint64_t{64} << 20);
    EXPECT_LE(here.least(), here.physical);
}

TEST(Footprint, GrowsWithWhatTheRunHolds) {
    BudgetShape fast;
    fast.trace = true;
    const Footprint plain = estimate_footprint(fast, 10000, 100);
    EXPECT_EQ(plain.model, 0u) << "the fast engine keeps no block RAM words";
    EXPECT_EQ(plain.boxes, 10000 * bytes_per_box(fast));
    EXPECT_EQ(plain.frames, 100 * bytes_per_frame(fast));

    BudgetShape clocked = fast;
    clocked.clocked = true;
    clocked.board.m = 32;
    const Footprint words = estimate_footprint(clocked, 10000, 100);
    EXPECT_EQ(words.model, clocked.board.block_ram_bytes(10000));
    EXPECT_LT(words.per_pair, plain.per_pair) << "the clocked engine keeps no more pairs than its buffer";

    BudgetShape everything = fast;
    everything.baselines = {"sap", "dbvt", "brute", "soa"};
    everything.repeat = 3;
    everything.pairs_out = true;
    everything.board.format = NumberFormat::parse("fixed16");
    const Footprint all = estimate_footprint(everything, 10000, 100);
    EXPECT_GT(all.boxes, plain.boxes);
    EXPECT_GT(all.frames, plain.frames);
    EXPECT_GT(all.per_pair, plain.per_pair);
    EXPECT_EQ(all.with_pairs(std::numeric_limits<uint64_t>::max() / 2), std::numeric_limits<uint64_t>::max())
        << "saturates, never wraps";
}

// Every library baseline costs memory a box; ODE's hash space an n-by-n bit
// matrix too, which dominates at 100,000 boxes.
TEST(Footprint, LibraryBaselinesCountTheirStructures) {
    BudgetShape none;
    none.trace = true;
    for (const char* name : {"fcl_tree", "fcl_sap", "fcl_interval", "fcl_hash", "ode_hash", "ode_quadtree", "ode_sap"}) {
        BudgetShape one = none;
        one.baselines = {name};
        EXPECT_GE(bytes_per_box(one), bytes_per_box(none) + 400) << name;
    }
    BudgetShape hash = none;
    hash.baselines = {"ode_hash"};
    const uint64_t objects = 100000;
    EXPECT_EQ(estimate_footprint(hash, objects, 1).boxes, objects * bytes_per_box(hash) + objects * objects / 8);
}

}  // namespace
}  // namespace cdvp
