#include "sw/timing/rapl_meter.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace cdvp {
namespace {

namespace fs = std::filesystem;

// A powercap tree of the kernel's shape under a scratch directory.
class FakePowercap : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("cdvp-rapl-" + std::to_string(::getpid()) + "-" +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root_);
        fs::create_directories(root_);
    }
    void TearDown() override { fs::remove_all(root_); }
    void domain(const std::string& name, const std::string& energy_uj, const std::string& range_uj) {
        fs::create_directories(root_ / name);
        std::ofstream(root_ / name / "energy_uj") << energy_uj << "\n";
        std::ofstream(root_ / name / "max_energy_range_uj") << range_uj << "\n";
    }
    fs::path root_;
};

TEST_F(FakePowercap, NoCountersMeansNotAvailable) {
    const RaplMeter meter(root_.string());
    EXPECT_FALSE(meter.available());
    EXPECT_EQ(meter.joules(), 0);
    EXPECT_FALSE(RaplMeter((root_ / "missing").string()).available());
}

TEST_F(FakePowercap, PackagesAreSummedAndSubDomainsLeftOut) {
    domain("intel-rapl:0", "2000000", "262143328850");
    domain("intel-rapl:1", "3000000", "262143328850");
    domain("intel-rapl:0:0", "900000000", "262143328850");  // the cores, inside package 0
    const RaplMeter meter(root_.string());
    ASSERT_TRUE(meter.available());
    EXPECT_DOUBLE_EQ(meter.joules(), 5.0);
}

TEST_F(FakePowercap, AWrappedCounterCountsFromItsRange) {
    domain("intel-rapl:0", "999000000", "1000000000");  // 999 J of a 1000 J range
    const RaplMeter meter(root_.string());
    const double start = meter.joules();
    std::ofstream(root_ / "intel-rapl:0" / "energy_uj") << "1000000\n";  // wrapped, then 1 J more
    EXPECT_NEAR(meter.joules_since(start), 2.0, 1e-9);
}

TEST_F(FakePowercap, AnUnreadableCounterIsNotAPackage) {
    domain("intel-rapl:0", "not a number", "1000");
    EXPECT_FALSE(RaplMeter(root_.string()).available());
}

}  // namespace
}  // namespace cdvp
