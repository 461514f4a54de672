// Signals at random moments of runs with several outputs: whatever the
// moment, the outputs are all the new ones or all the old ones, and no
// temporary or backup is left. CDVP_SIGNAL_STRESS_ITERATIONS sets the count
// (scripts/signal-stress.sh runs many).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

// The report without what is measured (every _native_ns time, the
// provenance with its load average, the load average at the end): two runs
// differ there only.
void drop_measured(nlohmann::json& value) {
    if (!value.is_object()) return;
    for (auto it = value.begin(); it != value.end();) {
        const std::string& key = it.key();
        const bool measured = key == "provenance" || key == "load_average_end" ||
                              (key.size() > 10 && key.compare(key.size() - 10, 10, "_native_ns") == 0);
        if (measured) {
            it = value.erase(it);
        } else {
            if (it->is_array()) {
                for (auto& item : *it) drop_measured(item);
            }
            drop_measured(*it);
            ++it;
        }
    }
}

std::string without_wall_times(const std::string& report) {
    nlohmann::json parsed = nlohmann::json::parse(report, nullptr, false);
    if (parsed.is_discarded()) return report;
    drop_measured(parsed);
    return parsed.dump(2);
}

const std::vector<std::string> kOutputs = {"pairs.csv", "r.json", "w.controller-states.txt", "w.dma-states.txt",
                                           "w.gtkw", "w.vcd"};

pid_t start_run(const fs::path& dir) {
    return spawn(dir, {"run", "--scene", "spheres", "--objects", "60", "--frames", "150", "--m", "2", "-q",
                       "--pairs-out", "pairs.csv", "--report", "r.json", "--vcd", "w.vcd"});
}

int iterations() {
    const char* text = std::getenv("CDVP_SIGNAL_STRESS_ITERATIONS");
    return text != nullptr ? std::max(1, std::atoi(text)) : 6;
}

TEST_F(Cli, SignalsAtRandomMomentsLeaveAllOutputsOrNone) {
    // A clean run: its outputs, and how long it takes.
    const auto clean_start = std::chrono::steady_clock::now();
    const pid_t clean = start_run(dir_);
    int status = 0;
    ASSERT_EQ(waitpid(clean, &status, 0), clean);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
    const auto duration = std::chrono::steady_clock::now() - clean_start;
    const std::string new_pairs = slurp(dir_ / "pairs.csv"), new_report = slurp(dir_ / "r.json");

    std::mt19937_64 random(std::random_device{}());
    const int signals[] = {SIGINT, SIGTERM, SIGHUP};
    int completed = 0, none = 0, all_then_signalled = 0;
    for (int k = 0; k < iterations(); ++k) {
        for (const std::string& name : kOutputs) write(name, "old\n");
        // Anywhere from the start to a little past the clean run's end,
        // half of the tries in its last fifth, where the commit is.
        const double fraction = k % 2 == 0 ? std::uniform_real_distribution<double>(0.0, 1.1)(random)
                                           : std::uniform_real_distribution<double>(0.8, 1.05)(random);
        const int signal_number = signals[random() % 3];
        const pid_t pid = start_run(dir_);
        ASSERT_GT(pid, 0);
        std::this_thread::sleep_for(std::chrono::duration_cast<std::chrono::microseconds>(duration * fraction));
        kill(pid, signal_number);
        ASSERT_EQ(waitpid(pid, &status, 0), pid);
        SCOPED_TRACE("try " + std::to_string(k) + ": signal " + std::to_string(signal_number) + " at " +
                     std::to_string(fraction) + " of the run");
        const bool signalled = WIFSIGNALED(status);
        ASSERT_TRUE(signalled ? WTERMSIG(status) == signal_number : WIFEXITED(status) && WEXITSTATUS(status) == 0)
            << status;
        std::vector<std::string> expected = kOutputs;
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(files(), expected) << "no temporary or backup left";
        std::size_t old_count = 0;
        for (const std::string& name : kOutputs) old_count += slurp(dir_ / name) == "old\n" ? 1 : 0;
        if (old_count == kOutputs.size()) {
            EXPECT_TRUE(signalled);
            ++none;
            continue;
        }
        EXPECT_EQ(old_count, 0u) << "a mix of old and new outputs";
        EXPECT_EQ(slurp(dir_ / "pairs.csv"), new_pairs);
        EXPECT_EQ(without_wall_times(slurp(dir_ / "r.json")), without_wall_times(new_report));
        EXPECT_NE(slurp(dir_ / "w.vcd").find("$enddefinitions"), std::string::npos);
        ++(signalled ? all_then_signalled : completed);
    }
    std::cout << "signal stress: " << iterations() << " runs: " << none << " killed with no output, "
              << all_then_signalled << " killed after committing every output, " << completed
              << " finished before the signal\n";
}

}  // namespace
}  // namespace cdvp::test
