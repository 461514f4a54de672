// What a timed call measures: CPU time leaves out time the thread did not
// run, wall time keeps it; a pin to a CPU the process may not use is refused;
// the speed probe measures a positive, steady time and its fast speed is a
// low quantile of its probes, also right after a call that evicted the caches.
#include <gtest/gtest.h>

#include <sched.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

#include "sw/timing/speed_probe.h"
#include "sw/timing/thread_timer.h"

namespace cdvp {
namespace {

volatile uint64_t g_sink = 0;

void spin_for(std::chrono::microseconds how_long) {
    const auto end = std::chrono::steady_clock::now() + how_long;
    uint64_t x = 1;
    while (std::chrono::steady_clock::now() < end) x = x * 6364136223846793005ull + 1;
    g_sink = x;
}

TEST(CallTimer, CpuTimeLeavesOutWhatTheThreadSpentAsleep) {
    const CallTiming t = CallTimer::time([] { std::this_thread::sleep_for(std::chrono::milliseconds(30)); });
    EXPECT_GE(t.wall_ns, 30e6);
    EXPECT_LT(t.cpu_ns, 5e6) << "asleep, the thread used next to no CPU";
    EXPECT_FALSE(t.migrated && t.involuntary_switches == 0 && t.cpu_ns > 1e9);
}

TEST(CallTimer, CpuTimeCountsWorkAndNeverExceedsTheWallByMoreThanAClockRead) {
    const CallTiming t = CallTimer::time([] { spin_for(std::chrono::microseconds(3000)); });
    EXPECT_GT(t.cpu_ns, 1e6) << "3 ms of work is at least 1 ms of CPU time, however busy the machine";
    EXPECT_LE(t.cpu_ns, t.wall_ns + 1e5);
}

TEST(CallTimer, AYieldToABusyThreadOnOneCpuIsSeenAsAnInvoluntarySwitchOrAMove) {
    // Pinned with a busy thread on the same CPU, a call of several scheduler
    // slices is pre-empted: the timing says so.
    cpu_set_t mine;
    CPU_ZERO(&mine);
    ASSERT_EQ(sched_getaffinity(0, sizeof mine, &mine), 0);
    int cpu = -1;
    for (int k = 0; k < CPU_SETSIZE && cpu < 0; ++k) {
        if (CPU_ISSET(k, &mine)) cpu = k;
    }
    ASSERT_GE(cpu, 0);
    ASSERT_EQ(pin_thread_to_cpu(static_cast<uint32_t>(cpu)), std::nullopt);
    std::atomic<bool> stop{false};
    std::thread busy([&] {
        pin_thread_to_cpu(static_cast<uint32_t>(cpu));
        while (!stop) g_sink = g_sink + 1;
    });
    const CallTiming t = CallTimer::time([] { spin_for(std::chrono::microseconds(200000)); });
    stop = true;
    busy.join();
    sched_setaffinity(0, sizeof mine, &mine);
    EXPECT_TRUE(t.disturbed()) << "200 ms beside a busy thread on one CPU";
    EXPECT_GT(t.involuntary_switches, 0u);
    EXPECT_LT(t.cpu_ns, 0.8 * t.wall_ns) << "the CPU was shared: CPU time is the thread's share of the wall";
}

TEST(PinThreadToCpu, ACpuThisProcessMayNotRunOnIsRefusedNamingTheAllowedOnes) {
    const std::optional<std::string> refused = pin_thread_to_cpu(1023);
    ASSERT_TRUE(refused.has_value());
    EXPECT_EQ(refused->rfind("CPU 1023 is not one this process may run on (", 0), 0u) << *refused;
}

// A probe must not read a CPU as slow because the call before it evicted the
// caches (a Bullet step of thousands of bodies, a large baseline frame): its
// timed pass runs on the lines its warm pass brought in. Each probe after an
// eviction is held to a probe right after it, so that a machine slowed by
// its neighbours slows both alike.
TEST(SpeedProbe, ReadsTheSameSpeedRightAfterACallThatEvictedTheCaches) {
    SpeedProbe probe;
    std::vector<unsigned char> evictor(std::size_t{32} << 20);  // past any L2 and most L3 shares
    std::vector<double> ratios;
    for (int k = 0; k < 31; ++k) {
        for (std::size_t at = 0; at < evictor.size(); at += 64) evictor[at] = static_cast<unsigned char>(evictor[at] + k);
        const double after_eviction = probe.time_ns();
        const double warm = probe.time_ns();
        ASSERT_GT(after_eviction, 0);
        ASSERT_GT(warm, 0);
        ratios.push_back(after_eviction / warm);
    }
    std::sort(ratios.begin(), ratios.end());
    // A cold timed pass reads 1.4x to 3x slow on every try.
    EXPECT_LE(ratios[15], 1.15) << "median of after-eviction / warm probes";
}

TEST(SpeedProbe, TheFastSpeedIsTheTenthPercentile) {
    EXPECT_DOUBLE_EQ(fast_probe_ns({}), 0);
    std::vector<double> probes;
    for (int k = 1; k <= 11; ++k) probes.push_back(100.0 * k);
    EXPECT_DOUBLE_EQ(fast_probe_ns(probes), 200);
}

}  // namespace
}  // namespace cdvp
