// A variant of the board RTL that the binary does not hold, compiled on
// first use (models/rtl_engine/rtl_model_cache.h), end to end through
// `cdvp run --fidelity rtl`: two first uses at once compile it once, a
// second use loads it, its runs match the clocked engine's and pass
// --lockstep, a damaged entry is compiled again, and what cannot be done
// (no verilator, a failed compile, a cache that cannot be made) is one line.
//
// One small variant (m = 3, a 5-pair FIFO, a 48-pair buffer, 128 boxes) is
// compiled once a test run, into CDVP_RTL_TEST_CACHE, by the fixture's
// setup test (TwoFirstUsesAtOnceCompileOnce); the tests after it load it.
// The key's inputs are checked in process, without compiling.
#include <sys/stat.h>

#include <openssl/evp.h>

#include <cstdlib>
#include <utility>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "models/rtl_engine/rtl_model_cache.h"
#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

const std::string kScene =
    "run --board adm-xrc-ii --m 3 --fifo-depth 5 --pair-buffer 48 --scene spheres --objects 100 --frames 3 -q";
const std::string kSpec = "m=3,format=float32,latency=2,fifo=5,buffer=48,tile=0,tile_latency=2,capacity=128";
const std::string kCompiling = "compiling the RTL for " + kSpec;
const fs::path kSharedCache = CDVP_RTL_TEST_CACHE;

// The cache's entries (directories), without the lock files beside them.
std::vector<fs::path> entries(const fs::path& cache) {
    std::vector<fs::path> found;
    for (const auto& item : fs::directory_iterator(cache)) {
        if (item.is_directory()) found.push_back(item.path());
    }
    return found;
}

nlohmann::json frames_without_wall_time(const std::string& report) {
    nlohmann::json frames = nlohmann::json::parse(report).at("frames");
    for (auto& frame : frames) {
        for (auto it = frame.begin(); it != frame.end();) {
            it = it.key().find("wall") != std::string::npos ? frame.erase(it) : std::next(it);
        }
    }
    return frames;
}

class RtlCompile : public Cli {
protected:
    // The clocked engine's pairs and frames for the scene, to hold the RTL to.
    void run_clocked() {
        const Result cycle = run(kScene + " --fidelity cycle --pairs-out c.csv --report c.json");
        ASSERT_EQ(cycle.status, 0) << cycle.err;
    }
    void expect_as_clocked(const std::string& stem) {
        EXPECT_EQ(slurp(dir_ / (stem + ".csv")), slurp(dir_ / "c.csv")) << stem;
        const nlohmann::json rtl = frames_without_wall_time(slurp(dir_ / (stem + ".json")));
        EXPECT_EQ(rtl, frames_without_wall_time(slurp(dir_ / "c.json"))) << stem;
        uint64_t pauses = 0, stalls = 0;
        for (const auto& frame : rtl) {
            pauses += frame.value("overflow_pauses", uint64_t{0});
            stalls += frame.value("stall_cycles", uint64_t{0});
        }
        EXPECT_GT(stalls, 0u) << "the scene should stall the 5-pair FIFO";
        EXPECT_GT(pauses, 0u) << "the scene should fill the 48-pair buffer";
    }
    static std::string cache_is(const fs::path& cache) { return "CDVP_RTL_CACHE='" + cache.string() + "'"; }
};

// Two runs that want the variant at once: one compiles, the other waits for
// it and loads what the first compiled; both run as the clocked engine does.
TEST_F(RtlCompile, TwoFirstUsesAtOnceCompileOnce) {
    fs::remove_all(kSharedCache);
    run_clocked();
    std::vector<pid_t> pids;
    for (const std::string stem : {"a", "b"}) {
        const std::string command = "cd '" + dir_.string() + "' && " + cache_is(kSharedCache) + " '" CDVP_BINARY "' " +
                                    kScene + " --fidelity rtl --pairs-out " + stem + ".csv --report " + stem +
                                    ".json 2> " + stem + ".err";
        const pid_t pid = fork();
        if (pid == 0) {
            execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
            _exit(127);
        }
        pids.push_back(pid);
    }
    for (const pid_t pid : pids) {
        int status = 0;
        waitpid(pid, &status, 0);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << slurp(dir_ / "a.err") << slurp(dir_ / "b.err");
    }
    const std::string errors[] = {slurp(dir_ / "a.err"), slurp(dir_ / "b.err")};
    // One line each: the one that compiled says so, the other that it waited.
    const std::string compiling = "cdvp run: " + kCompiling + " (first use; cached in " + kSharedCache.string() + "/";
    const std::string waited = "cdvp run: waiting for another process " + kCompiling + " into " + kSharedCache.string();
    const int compiled = (errors[0].rfind(compiling, 0) == 0) + (errors[1].rfind(compiling, 0) == 0);
    EXPECT_EQ(compiled, 1) << errors[0] << errors[1];
    EXPECT_TRUE(errors[0].rfind(waited, 0) == 0 || errors[1].rfind(waited, 0) == 0) << errors[0] << errors[1];
    for (const std::string& e : errors) EXPECT_EQ(std::count(e.begin(), e.end(), '\n'), 1) << e;
    expect_as_clocked("a");
    expect_as_clocked("b");
    // One entry, stamped, and nothing left of the compile but its log.
    const std::vector<fs::path> made = entries(kSharedCache);
    ASSERT_EQ(made.size(), 1u);
    EXPECT_EQ(made[0].filename().string().rfind("m3_float32_l2_f5_b48_t0_s2_a7-", 0), 0u) << made[0];
    for (const char* file : {"model.so", "stamp.txt", "key.txt", "build.log"}) {
        EXPECT_TRUE(fs::exists(made[0] / file)) << file;
    }
    EXPECT_FALSE(fs::exists(made[0] / "verilated")) << "the generated sources and objects are removed";
    EXPECT_NE(slurp(made[0] / "stamp.txt").find("spec " + kSpec + "\n"), std::string::npos);
}

// Later runs load the model without compiling (the entry untouched), run as
// the clocked engine does, and the clocked engine beside it agrees edge by edge.
TEST_F(RtlCompile, ASecondUseLoadsFromTheCacheAndPassesLockstep) {
    const std::vector<fs::path> made = entries(kSharedCache);
    ASSERT_EQ(made.size(), 1u) << "the fixture compiled the variant";
    const std::string stamp = slurp(made[0] / "stamp.txt");
    struct stat before {};
    ASSERT_EQ(stat((made[0] / "model.so").c_str(), &before), 0);
    run_clocked();
    for (const std::string stem : {"r", "l"}) {
        const std::string lockstep = stem == "l" ? " --lockstep" : "";
        const Result r = run(kScene + " --fidelity rtl" + lockstep + " --pairs-out " + stem + ".csv --report " + stem +
                                 ".json",
                             cache_is(kSharedCache));
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err, "") << "no compile, nothing to say";
        expect_as_clocked(stem);
    }
    struct stat after {};
    ASSERT_EQ(stat((made[0] / "model.so").c_str(), &after), 0);
    EXPECT_EQ(after.st_ino, before.st_ino);
    EXPECT_EQ(after.st_mtim.tv_sec, before.st_mtim.tv_sec);
    EXPECT_EQ(slurp(made[0] / "stamp.txt"), stamp);
    EXPECT_EQ(entries(kSharedCache).size(), 1u);
}

// A shared object cut short (a disk filled while copying, say) is noticed by
// its digest and compiled again, not loaded.
TEST_F(RtlCompile, ADamagedEntryIsCompiledAgain) {
    const std::vector<fs::path> made = entries(kSharedCache);
    ASSERT_EQ(made.size(), 1u) << "the fixture compiled the variant";
    const fs::path cache = dir_ / "cache";
    fs::create_directories(cache);
    const fs::path entry = cache / made[0].filename();
    fs::copy(made[0], entry, fs::copy_options::recursive);
    fs::resize_file(entry / "model.so", fs::file_size(entry / "model.so") / 2);
    run_clocked();
    const Result r = run(kScene + " --fidelity rtl --pairs-out r.csv --report r.json", cache_is(cache));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "cdvp run: " + kCompiling +
                         " again (the cached model was damaged: model.so differs from its stamp; cached in " +
                         entry.string() + ")\n");
    expect_as_clocked("r");
    EXPECT_EQ(fs::file_size(entry / "model.so"), fs::file_size(made[0] / "model.so"));
    const Result again = run(kScene + " --fidelity rtl --pairs-out r.csv", cache_is(cache));
    EXPECT_EQ(again.status, 0) << again.err;
    EXPECT_EQ(again.err, "");
}

TEST_F(RtlCompile, WithoutVerilatorTheRunIsRefusedInOneLine) {
    const fs::path cache = dir_ / "cache";
    const Result r = run(kScene + " --fidelity rtl --report r.json", cache_is(cache) + " PATH=/nonexistent");
    expect_refusal(r, "cdvp run: fidelity rtl: " + kCompiling + " needs verilator, which is not on PATH");
    EXPECT_FALSE(fs::exists(cache)) << "nothing is made before the tools are found";
    EXPECT_FALSE(fs::exists(dir_ / "r.json"));
}

// A compile that fails names the tool and its log, which stays; nothing
// else is left in the cache. (A stand-in verilator fails as a broken RTL would.)
TEST_F(RtlCompile, AFailedCompileIsOneLineNamingItsLog) {
    const fs::path tools = dir_ / "tools", cache = dir_ / "cache";
    fs::create_directories(tools);
    write("tools/verilator",
          "#!/bin/sh\n[ \"$1\" = --version ] && { echo 'Verilator 5.006 stand-in'; exit 0; }\n"
          "echo '%Error: collision_board_top.v:1: a stand-in failure' >&2\nexit 1\n");
    fs::permissions(tools / "verilator", fs::perms::owner_all);
    const Result r = run(kScene + " --fidelity rtl", cache_is(cache) + " PATH='" + tools.string() + ":" + getenv("PATH") + "'");
    EXPECT_EQ(r.status, 2);
    // The compile's notice, then the failure's one line.
    std::istringstream lines(r.err);
    std::string notice, failure, more;
    std::getline(lines, notice);
    std::getline(lines, failure);
    EXPECT_EQ(notice.rfind("cdvp run: " + kCompiling + " (first use; cached in " + cache.string(), 0), 0u) << r.err;
    EXPECT_EQ(failure.rfind("cdvp run: fidelity rtl: " + kCompiling +
                                " failed: verilator --build exited with status 1; its log: " + cache.string() +
                                "/m3_float32",
                            0),
              0u)
        << r.err;
    EXPECT_FALSE(std::getline(lines, more)) << r.err;
    const std::string log = failure.substr(failure.find("its log: ") + 9);
    EXPECT_EQ(log.substr(log.size() - 11), ".failed.log") << log;
    EXPECT_NE(slurp(log).find("a stand-in failure"), std::string::npos) << log;
    EXPECT_TRUE(entries(cache).empty()) << "no entry, no partial directory";
}

TEST_F(RtlCompile, ACacheThatCannotBeMadeIsOneLine) {
    write("file", "not a directory");
    const Result r = run(kScene + " --fidelity rtl", cache_is(dir_ / "file" / "cache"));
    expect_refusal(r, "cdvp run: fidelity rtl: cannot create the RTL model cache " + (dir_ / "file" / "cache").string() +
                          " (CDVP_RTL_CACHE sets another): Not a directory");
}

// The key digests what the model is made of: another RTL, build or
// variant is another entry; the same inputs the same one.
TEST(RtlModelKey, ChangesWithTheRtlTheBuildAndTheVariant) {
    const fs::path root = fs::temp_directory_path() / ("cdvp-rtl-kit-" + std::to_string(getpid()));
    fs::remove_all(root);
    const RtlKit source = rtl_kit_at(CDVP_SOURCE_DIR);
    for (const std::string& file : source.files()) {
        fs::create_directories((root / file).parent_path());
        fs::copy_file(source.path(file), root / file);
    }
    const RtlKit copy = rtl_kit_at(root.string());
    const RtlBuild build = rtl_build();
    RtlVariant variant;
    const std::string key = rtl_model_key_text(variant, build, copy);
    EXPECT_EQ(key, rtl_model_key_text(variant, build, source)) << "the kit's content, not its place";
    RtlBuild other_build = build;
    other_build.git_commit = "0123";
    EXPECT_NE(rtl_model_key_text(variant, other_build, copy), key);
    RtlVariant other_variant = variant;
    other_variant.fifo_depth = 16;
    EXPECT_NE(rtl_model_key_text(other_variant, build, copy), key);
    std::ofstream(root / "models/board/rtl/board_ram.v", std::ios::app) << "// changed\n";
    EXPECT_NE(rtl_model_key_text(variant, build, copy), key);
    fs::remove(root / "models/common/aabb.h");
    try {
        rtl_model_key_text(variant, build, copy);
        ADD_FAILURE() << "a kit file missing";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("models/common/aabb.h: cannot read the RTL sources"), std::string::npos)
            << e.what();
    }
    fs::remove_all(root);
}


// Where the cache is, from the environment: only absolute paths; a relative
// XDG_CACHE_HOME is ignored (the XDG Base Directory rules), and with no HOME
// besides there is no cache, never one in the working directory.
class RtlModelCacheDirectory : public ::testing::Test {
protected:
    void SetUp() override {
        for (const char* name : {"CDVP_RTL_CACHE", "XDG_CACHE_HOME", "HOME"}) {
            if (const char* value = std::getenv(name)) saved_.emplace_back(name, value);
            ::unsetenv(name);
        }
    }
    void TearDown() override {
        for (const char* name : {"CDVP_RTL_CACHE", "XDG_CACHE_HOME", "HOME"}) ::unsetenv(name);
        for (const auto& [name, value] : saved_) ::setenv(name.c_str(), value.c_str(), 1);
    }
    std::vector<std::pair<std::string, std::string>> saved_;
};

TEST_F(RtlModelCacheDirectory, ARelativeXdgCacheHomeIsIgnored) {
    ::setenv("HOME", "/home/someone", 1);
    ::setenv("XDG_CACHE_HOME", "relative/cache", 1);
    EXPECT_EQ(RtlModelCache::default_directory(), "/home/someone/.cache/cdvp/rtl");
    ::setenv("XDG_CACHE_HOME", "/var/cache/someone", 1);
    EXPECT_EQ(RtlModelCache::default_directory(), "/var/cache/someone/cdvp/rtl");
    ::setenv("CDVP_RTL_CACHE", "/srv/rtl", 1);
    EXPECT_EQ(RtlModelCache::default_directory(), "/srv/rtl");
}

TEST_F(RtlModelCacheDirectory, WithoutHomeThereIsNoCacheAndTheRunIsRefusedInOneLine) {
    ::setenv("XDG_CACHE_HOME", "relative/cache", 1);
    EXPECT_EQ(RtlModelCache::default_directory(), "");
    ::unsetenv("XDG_CACHE_HOME");
    EXPECT_EQ(RtlModelCache::default_directory(), "");
    ::setenv("HOME", "relative-home", 1);
    EXPECT_EQ(RtlModelCache::default_directory(), "");
    const RtlBuild build = rtl_build();
    const RtlKit kit = rtl_kit_at(CDVP_SOURCE_DIR);
    for (const std::string& directory : {std::string(), std::string("relative/rtl")}) {
        RtlModelCache cache(directory, build, kit, [](const std::string& line) {
            throw std::runtime_error("would compile: " + line);
        });
        try {
            cache.load(RtlVariant{});
            ADD_FAILURE() << "loaded from '" << directory << "'";
        } catch (const InputError& e) {
            const std::string line = e.what();
            EXPECT_NE(line.find(directory.empty() ? "set CDVP_RTL_CACHE (or HOME) to an absolute directory"
                                                  : "CDVP_RTL_CACHE: relative/rtl is not an absolute path"),
                      std::string::npos)
                << line;
            EXPECT_EQ(line.find('\n'), std::string::npos) << line;
        }
    }
}

std::string sha256_of(const std::string& bytes) {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int size = 0;
    EXPECT_EQ(EVP_Digest(bytes.data(), bytes.size(), digest, &size, EVP_sha256(), nullptr), 1);
    std::string hex;
    for (unsigned int k = 0; k < size; ++k) hex += {"0123456789abcdef"[digest[k] >> 4], "0123456789abcdef"[digest[k] & 15]};
    return hex;
}

// An entry of the default variant in a cache of its own: a stamp naming its
// key and an object that is no shared object, standing in for a compiled one
// (a private one goes on to be compiled again: the notice says so).
class RtlModelCacheEntry : public ::testing::Test {
protected:
    void SetUp() override {
        fs::remove_all(cache_);
        const std::string key = sha256_of(rtl_model_key_text(variant_, build_, kit_));
        entry_ = cache_ / (variant_.name() + "-" + key.substr(0, 16));
        fs::create_directories(entry_);
        const std::string object = "not a shared object";
        std::ofstream(entry_ / "model.so", std::ios::binary) << object;
        std::ofstream(entry_ / "stamp.txt", std::ios::binary)
            << "key " << key << "\nmodel.so " << object.size() << ' ' << sha256_of(object) << '\n';
    }
    void TearDown() override { fs::remove_all(cache_); }
    // "loaded", "refused: LINE" or what the notice or another error said.
    std::string outcome() {
        RtlModelCache loader(cache_.string(), build_, kit_, [](const std::string& line) {
            throw std::runtime_error("would compile: " + line);
        });
        try {
            loader.load(variant_);
            return "loaded";
        } catch (const InputError& e) {
            return std::string("refused: ") + e.what();
        } catch (const std::exception& e) {
            return e.what();
        }
    }
    const fs::path cache_ = fs::temp_directory_path() / ("cdvp-rtl-private-" + std::to_string(getpid()));
    const RtlBuild build_ = rtl_build();
    const RtlKit kit_ = rtl_kit_at(CDVP_SOURCE_DIR);
    const RtlVariant variant_;
    fs::path entry_;
};

// dlopen runs an entry's code: an entry others can write to (or that is not
// the user's) is refused in one line naming it, not loaded and not compiled
// over.
TEST_F(RtlModelCacheEntry, AGroupWritableEntryIsRefused) {
    const fs::path& entry = entry_;
    for (const fs::path& path : {entry, entry / "model.so", entry / "stamp.txt"}) {
        for (const auto perms : {fs::perms::group_write, fs::perms::others_write}) {
            ASSERT_EQ(chmod(entry.c_str(), 0755), 0);
            ASSERT_EQ(chmod((entry / "model.so").c_str(), 0644), 0);
            ASSERT_EQ(chmod((entry / "stamp.txt").c_str(), 0644), 0);
            fs::permissions(path, perms, fs::perm_options::add);
            const std::string result = outcome();
            EXPECT_EQ(result, "refused: fidelity rtl: the RTL model cache's " + path.string() +
                                  " is writable by group or others (expected your own, writable only by you; "
                                  "remove the entry to compile it again)");
        }
    }
    ASSERT_EQ(chmod(entry.c_str(), 0755), 0);
    ASSERT_EQ(chmod((entry / "model.so").c_str(), 0644), 0);
    ASSERT_EQ(chmod((entry / "stamp.txt").c_str(), 0644), 0);
    EXPECT_EQ(outcome().rfind("would compile: ", 0), 0u) << "a private entry is looked at";
    // A symbolic link to an object elsewhere is not followed.
    fs::rename(entry / "model.so", cache_ / "elsewhere.so");
    fs::create_symlink(cache_ / "elsewhere.so", entry / "model.so");
    EXPECT_EQ(outcome(), "refused: fidelity rtl: the RTL model cache's " + (entry / "model.so").string() +
                             " is a symbolic link (expected your own, writable only by you; remove the entry to "
                             "compile it again)");
}

// A stamp or object of the user's own that is a FIFO (which would hold the
// open, or the read, forever) or a stamp larger than any cdvp writes (read
// without limit, as /dev/zero would be) is refused unread in one line naming
// it; the alarm fails a test that hangs.
TEST_F(RtlModelCacheEntry, AStampOrObjectThatIsNoRegularFileOrTooBigIsRefusedUnread) {
    alarm(60);
    const std::string stamp = slurp(entry_ / "stamp.txt");
    fs::remove(entry_ / "stamp.txt");
    ASSERT_EQ(mkfifo((entry_ / "stamp.txt").c_str(), 0600), 0);
    EXPECT_EQ(outcome(), "refused: fidelity rtl: the RTL model cache's " + (entry_ / "stamp.txt").string() +
                             ": cannot open: not a regular file; expected the stamp cdvp wrote (remove the entry to "
                             "compile it again)");
    fs::remove(entry_ / "stamp.txt");
    std::ofstream(entry_ / "stamp.txt", std::ios::binary) << stamp << std::string(1 << 20, '#');
    EXPECT_EQ(outcome(), "refused: fidelity rtl: the RTL model cache's " + (entry_ / "stamp.txt").string() +
                             ": larger than 65536 bytes; not the stamp cdvp wrote (remove the entry to compile it "
                             "again)");
    std::ofstream(entry_ / "stamp.txt", std::ios::binary) << stamp;
    fs::remove(entry_ / "model.so");
    ASSERT_EQ(mkfifo((entry_ / "model.so").c_str(), 0600), 0);
    EXPECT_EQ(outcome(), "refused: fidelity rtl: the RTL model cache's " + (entry_ / "model.so").string() +
                             ": cannot open: not a regular file; expected the model cdvp compiled (remove the entry "
                             "to compile it again)");
    alarm(0);
}

}  // namespace
}  // namespace cdvp::test
