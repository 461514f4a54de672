// The cdvp command line, run as users run it: a fresh directory per test.
#pragma once

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cdvp::test {

namespace fs = std::filesystem;

struct Result {
    int status;
    std::string out;
    std::string err;
};

inline std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// A run report (--report FILE) as JSON.
inline nlohmann::json report_of(const fs::path& path) { return nlohmann::json::parse(slurp(path)); }

class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        // A parameterised test's name has a '/' (Name/Case): one directory
        // of it, not two, so that TearDown leaves nothing behind.
        std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        std::replace(name.begin(), name.end(), '/', '-');
        dir_ = fs::temp_directory_path() / ("cdvp-cli-" + std::to_string(::getpid()) + "-" + name);
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        // Runs look for a host profile in the user's config directory: each
        // test gets an empty one of its own, so none finds the developer's.
        ::setenv("XDG_CONFIG_HOME", (dir_ / ".config").c_str(), 1);
        // And a cache of its own beside it (the machine's remembered speed
        // starts empty), outside the directory whose files tests list.
        cache_ = dir_.string() + ".cache";
        fs::remove_all(cache_);
        ::setenv("XDG_CACHE_HOME", cache_.c_str(), 1);
#ifdef CDVP_TEST_RTL_CACHE
        ::setenv("CDVP_RTL_CACHE", CDVP_TEST_RTL_CACHE, 0);  // a test's own CDVP_RTL_CACHE=... still wins
#endif
    }
    void TearDown() override {
        fs::remove_all(dir_);
        fs::remove_all(cache_);
    }

    // Runs `cdvp ARGS` (a shell command line) in the test's directory, with
    // 'environment' ("NAME=value ...") set.
    Result run(const std::string& args, const std::string& environment = "") {
        const fs::path out = dir_ / ".stdout", err = dir_ / ".stderr";
        const std::string command = "cd '" + dir_.string() + "' && " + environment + " '" CDVP_BINARY "' " + args +
                                    " > '" + out.string() + "' 2> '" + err.string() + "' < /dev/null";
        const int raw = std::system(command.c_str());
        Result r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
        fs::remove(out);
        fs::remove(err);
        return r;
    }
    fs::path write(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name, std::ios::binary) << text;
        return dir_ / name;
    }
    std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
    static std::string trace(const std::string& name) { return CDVP_SOURCE_DIR "/traces/" + name; }
    static std::string preset(const std::string& name) { return CDVP_SOURCE_DIR "/platform/boards/" + name + ".json"; }

    fs::path dir_;
    fs::path cache_;  // $XDG_CACHE_HOME of the runs
};

// Bad input refused: status 2 and one line on stderr that starts with 'start'.
inline void expect_refusal(const Result& r, const std::string& start, const std::string& context = "") {
    EXPECT_EQ(r.status, 2) << context << ": " << r.err.substr(0, 300);
    EXPECT_EQ(r.err.rfind(start, 0), 0u) << context << ": " << r.err.substr(0, 300);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << context << ": one line";
}

// Starts `cdvp ARGS` in 'dir' with no shell in between, output discarded.
inline pid_t spawn(const fs::path& dir, const std::vector<std::string>& args) {
    const pid_t pid = fork();
    if (pid == 0) {
        if (chdir(dir.c_str()) != 0) _exit(127);
        const int null = open("/dev/null", O_RDWR);
        dup2(null, 0);
        dup2(null, 1);
        dup2(null, 2);
        std::vector<char*> argv{const_cast<char*>(CDVP_BINARY)};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(CDVP_BINARY, argv.data());
        _exit(127);
    }
    return pid;
}

}  // namespace cdvp::test
