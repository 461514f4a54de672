#include "models/rtl_engine/rtl_model_cache.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <openssl/evp.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>

#include "models/common/input_path.h"
#include "models/common/user_directories.h"
#include "models/common/user_text.h"
#include "models/rtl_engine/rtl_model_compile.h"

namespace cdvp {

namespace fs = std::filesystem;

namespace {

constexpr const char* kModel = "model.so";
constexpr const char* kStamp = "stamp.txt";
constexpr std::size_t kKeyDigits = 16;

std::string sha256_hex(const std::string& bytes) {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int size = 0;
    if (EVP_Digest(bytes.data(), bytes.size(), digest, &size, EVP_sha256(), nullptr) != 1) {
        throw std::runtime_error("OpenSSL: SHA-256 failed");
    }
    static const char kHex[] = "0123456789abcdef";
    std::string hex;
    for (unsigned int k = 0; k < size; ++k) hex += {kHex[digest[k] >> 4], kHex[digest[k] & 15]};
    return hex;
}

// What the cache reads back, each through the one reader of input files: a
// stamp is a few lines; an object, a kit file, some MiB.
constexpr std::size_t kMaxStampBytes = 64 << 10;
constexpr std::size_t kMaxFileBytes = std::size_t{1} << 30;

// "bytes sha256" of a file, or nothing when there is none; InputError naming
// it when it is no regular file or is larger than max_bytes.
std::optional<std::string> file_digest(const std::string& path, const std::string& what,
                                       std::size_t max_bytes = kMaxFileBytes) {
    const std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> context(EVP_MD_CTX_new(), EVP_MD_CTX_free);
    if (!context || EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) != 1) {
        throw std::runtime_error("OpenSSL: SHA-256 failed");
    }
    uint64_t bytes = 0;
    const bool there = read_input_blocks({path, what, max_bytes, true}, [&](const char* data, std::size_t size) {
        if (EVP_DigestUpdate(context.get(), data, size) != 1) throw std::runtime_error("OpenSSL: SHA-256 failed");
        bytes += size;
    });
    if (!there) return std::nullopt;
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int size = 0;
    if (EVP_DigestFinal_ex(context.get(), digest, &size) != 1) throw std::runtime_error("OpenSSL: SHA-256 failed");
    static const char kHex[] = "0123456789abcdef";
    std::string hex;
    for (unsigned int k = 0; k < size; ++k) hex += {kHex[digest[k] >> 4], kHex[digest[k] & 15]};
    return std::to_string(bytes) + " " + hex;
}

std::string join(const std::vector<std::string>& words) {
    std::string text;
    for (const std::string& w : words) text += (text.empty() ? "" : " ") + w;
    return text;
}

// The value of the stamp's line "key VALUE", or empty.
std::string stamp_value(const std::string& stamp, const std::string& key) {
    std::istringstream lines(stamp);
    for (std::string line; std::getline(lines, line);) {
        if (line.compare(0, key.size() + 1, key + " ") == 0) return line.substr(key.size() + 1);
    }
    return {};
}

// Creates the cache directory and its parents; one line naming it otherwise.
void make_directory(const std::string& directory) {
    std::error_code ec;
    fs::create_directories(directory, ec);
    if (ec) {
        throw_os_error("fidelity rtl: cannot create the RTL model cache " + printable(directory) +
                           " (CDVP_RTL_CACHE sets another)",
                       ec.value());
    }
}

// An exclusive lock on a file beside the entry, held while it lives. The
// lock file stays (removing it would let a third process lock a new one).
class EntryLock {
public:
    EntryLock(const std::string& path, const std::function<void()>& on_wait) {
        fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd_ < 0) throw_os_error("fidelity rtl: cannot write the RTL model cache's lock " + printable(path), errno);
        if (flock(fd_, LOCK_EX | LOCK_NB) == 0) return;
        on_wait();
        while (flock(fd_, LOCK_EX) != 0) {
            if (errno != EINTR) {
                const int error = errno;
                close(fd_);
                throw_os_error("fidelity rtl: cannot lock " + printable(path), error);
            }
        }
    }
    ~EntryLock() { close(fd_); }
    EntryLock(const EntryLock&) = delete;
    EntryLock& operator=(const EntryLock&) = delete;

private:
    int fd_ = -1;
};

// Why a path of an entry may not be loaded from, or empty: dlopen runs its
// code, so the entry and its files must be the user's own and writable by
// nobody else (nor a symbolic link to something that may not be). A path
// that is missing is left to the checks after.
std::string not_private(const std::string& path) {
    struct stat st {};
    if (lstat(path.c_str(), &st) != 0) return {};
    if (S_ISLNK(st.st_mode)) return "is a symbolic link";
    if (st.st_uid != geteuid()) return "is owned by another user (uid " + std::to_string(st.st_uid) + ")";
    if ((st.st_mode & (S_IWGRP | S_IWOTH)) != 0) return "is writable by group or others";
    return {};
}

// Refuses, in one line naming the path, an entry someone else could have
// put code in.
void check_private(const std::string& entry) {
    for (const std::string& path : {entry, entry + "/" + kStamp, entry + "/" + kModel}) {
        const std::string why = not_private(path);
        if (!why.empty()) {
            throw InputError("fidelity rtl: the RTL model cache's " + printable(path) + " " + why +
                             " (expected your own, writable only by you; remove the entry to compile it again)");
        }
    }
}

// Takes away group and others' write permission from what a compile made.
void make_private(const std::string& path) {
    std::error_code ec;
    for (const auto& item : fs::recursive_directory_iterator(path, ec)) {
        if (item.is_symlink(ec)) continue;
        fs::permissions(item.path(), fs::perms::group_write | fs::perms::others_write, fs::perm_options::remove, ec);
    }
    fs::permissions(path, fs::perms::group_write | fs::perms::others_write, fs::perm_options::remove, ec);
}

// The entry's maker if it checks out: the stamp names this key and the
// shared object's size and digest, which loads and has the entry point.
// Otherwise nothing, and `damage` says why (empty: no entry at all).
RtlBoardMaker open_entry(const std::string& entry, const std::string& key, std::string& damage) {
    damage.clear();
    std::error_code ec;
    if (!fs::exists(entry, ec)) return nullptr;
    check_private(entry);
    std::optional<std::string> stamp, digest;
    const std::string model = entry + "/" + kModel;
    try {  // a stamp or object that is a FIFO, a device or huge: refused unread, as one others could write
        stamp = read_input_file({entry + "/" + kStamp, "the stamp cdvp wrote", kMaxStampBytes, true});
        if (stamp && stamp_value(*stamp, "key") == key) digest = file_digest(model, "the model cdvp compiled");
    } catch (const InputError& e) {
        throw InputError("fidelity rtl: the RTL model cache's " + std::string(e.what()) +
                         " (remove the entry to compile it again)");
    }
    if (!stamp) {
        damage = "no " + std::string(kStamp);
        return nullptr;
    }
    if (stamp_value(*stamp, "key") != key) {
        damage = std::string(kStamp) + " names another key";
        return nullptr;
    }
    if (!digest || *digest != stamp_value(*stamp, kModel)) {
        damage = std::string(kModel) + (digest ? " differs from its stamp" : " is missing");
        return nullptr;
    }
    // Never closed: the models made from it live as long as the process may.
    void* handle = dlopen(model.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
        damage = std::string("dlopen: ") + dlerror();
        return nullptr;
    }
    auto maker = reinterpret_cast<RtlBoardMaker>(dlsym(handle, kRtlBoardMakerSymbol));
    if (maker == nullptr) damage = std::string(kModel) + " has no " + kRtlBoardMakerSymbol;
    return maker;
}

void remove_tree(const std::string& path) {
    std::error_code ec;
    fs::remove_all(path, ec);
}

// Directories left by a compile that did not finish (its process killed):
// only the lock's holder compiles, so any that exist are dead.
void remove_partials(const std::string& entry) {
    const fs::path path(entry);
    const std::string prefix = path.filename().string() + ".partial-";
    std::error_code ec;
    for (const auto& item : fs::directory_iterator(path.parent_path(), ec)) {
        if (item.path().filename().string().rfind(prefix, 0) == 0) remove_tree(item.path().string());
    }
}

// Compiles into a fresh directory beside the entry, stamps it last and
// renames it into place (over a damaged entry, moved aside first).
void build_entry(const RtlVariant& variant, const RtlToolchain& tools, const RtlBuild& build, const RtlKit& kit,
                 const std::string& entry, const std::string& key, const std::string& key_text) {
    remove_partials(entry);
    std::string pattern = entry + ".partial-XXXXXX";
    if (mkdtemp(pattern.data()) == nullptr) {
        throw_os_error("fidelity rtl: cannot write the RTL model cache " + printable(entry), errno);
    }
    const std::string partial = pattern;
    const std::string failed_log = entry + ".failed.log";
    const auto started = std::chrono::steady_clock::now();
    std::string version;
    try {
        version = compile_rtl_model(variant, tools, build, kit, partial, partial + "/build.log");
    } catch (const std::runtime_error& e) {
        // The log outlives the partial directory, at the path the message names.
        std::error_code ec;
        fs::rename(partial + "/build.log", failed_log, ec);
        remove_tree(partial);
        std::string why = e.what();
        if (const std::size_t at = why.find(partial + "/build.log"); at != std::string::npos && !ec) {
            why.replace(at, partial.size() + 10, failed_log);
        }
        const std::string line = "fidelity rtl: compiling the RTL for " + variant.spec() + " failed: " + why;
        if (dynamic_cast<const SystemError*>(&e) != nullptr) throw SystemError(line);
        throw InputError(line);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    remove_tree(partial + "/verilated");  // sources and objects: the shared object holds all of it
    const std::optional<std::string> digest = file_digest(partial + "/" + kModel, "the model Verilator's build made");
    if (!digest) throw std::runtime_error("Verilator's build left no " + std::string(kModel) + " in " + partial);
    std::ofstream(partial + "/key.txt", std::ios::binary) << key_text;
    std::ostringstream stamp;
    stamp << "key " << key << "\nspec " << variant.spec() << '\n'
          << kModel << ' ' << *digest << "\nverilator " << version << "\ncompile_seconds " << seconds << '\n';
    std::ofstream out(partial + "/" + kStamp, std::ios::binary);
    out << stamp.str();
    out.close();
    if (!out) {
        const int error = errno;
        remove_tree(partial);
        throw_os_error("fidelity rtl: cannot write the RTL model cache " + printable(entry), error);
    }
    make_private(partial);
    std::error_code ec;
    if (fs::exists(entry, ec)) {
        const std::string aside = partial + ".damaged";
        fs::rename(entry, aside, ec);
        remove_tree(aside);
    }
    fs::rename(partial, entry, ec);
    if (ec) {
        remove_tree(partial);
        throw_os_error("fidelity rtl: cannot move the compiled RTL model into " + printable(entry), ec.value());
    }
    fs::remove(failed_log, ec);
}

std::string& notice_program() {
    static std::string program = "cdvp";
    return program;
}

}  // namespace

std::string rtl_model_key_text(const RtlVariant& variant, const RtlBuild& build, const RtlKit& kit) {
    std::ostringstream text;
    text << "cdvp RTL model\nvariant " << variant.spec() << "\ncdvp " << build.version << "\ngit_commit "
         << build.git_commit << "\ncompiler " << build.compiler << " (" << build.compiler_path << ")\nflags "
         << build.flags << "\nverilator_arguments " << join(build.verilator_arguments) << "\nmake_options "
         << join(rtl_model_make_options()) << '\n';
    for (const std::string& file : kit.files()) {
        std::optional<std::string> digest;
        try {
            digest = file_digest(kit.path(file), "an RTL source");
        } catch (const InputError&) {
        }
        if (!digest) {
            throw InputError("fidelity rtl: " + printable(kit.path(file)) +
                             ": cannot read the RTL sources a model is compiled from (cmake --install puts them in "
                             "share/cdvp/rtl)");
        }
        text << "file " << file << ' ' << *digest << '\n';
    }
    return text.str();
}

RtlModelCache::RtlModelCache(std::string directory, const RtlBuild& build, const RtlKit& kit, Notice notice)
    : directory_(std::move(directory)), build_(build), kit_(kit), notice_(std::move(notice)) {}

std::string RtlModelCache::default_directory() {
    const char* own = std::getenv("CDVP_RTL_CACHE");
    if (own != nullptr && own[0] != '\0') return own;
    const std::string cache = user_base_directory("XDG_CACHE_HOME", ".cache");
    return cache.empty() ? cache : cache + "/cdvp/rtl";
}

RtlBoardMaker RtlModelCache::load(const RtlVariant& variant) {
    // Code is loaded only from where the user said, never from wherever the
    // process happens to run.
    if (directory_.empty()) {
        throw InputError("fidelity rtl: " + variant.spec() +
                         " is compiled into a cache, and there is none (neither XDG_CACHE_HOME nor HOME is an "
                         "absolute path); set CDVP_RTL_CACHE (or HOME) to an absolute directory");
    }
    if (directory_[0] != '/') {
        throw InputError("CDVP_RTL_CACHE: " + printable(directory_) +
                         " is not an absolute path (expected one: the RTL model cache holds code cdvp loads)");
    }
    const std::string key_text = rtl_model_key_text(variant, build_, kit_);
    const std::string key = sha256_hex(key_text);
    const std::string entry = directory_ + "/" + variant.name() + "-" + key.substr(0, kKeyDigits);
    std::string damage;
    if (const RtlBoardMaker maker = open_entry(entry, key, damage)) return maker;
    const std::string what = "compiling the RTL for " + variant.spec();
    const RtlToolchain tools = find_rtl_toolchain(build_, "fidelity rtl: " + what);
    make_directory(directory_);
    const EntryLock lock(entry + ".lock", [&] {
        notice_("waiting for another process " + what + " into " + entry);
    });
    // Whoever held the lock may have made it meanwhile.
    if (const RtlBoardMaker maker = open_entry(entry, key, damage)) return maker;
    notice_(damage.empty() ? what + " (first use; cached in " + entry + ")"
                           : what + " again (the cached model was damaged: " + damage + "; cached in " + entry + ")");
    build_entry(variant, tools, build_, kit_, entry, key, key_text);
    if (const RtlBoardMaker maker = open_entry(entry, key, damage)) return maker;
    throw std::runtime_error("the RTL model just compiled into " + entry + " does not load: " + damage);
}

RtlModelCache& process_rtl_model_cache() {
    static RtlModelCache cache(RtlModelCache::default_directory(), rtl_build(), rtl_kit(), [](const std::string& line) {
        std::cerr << notice_program() << ": " << line << std::endl;
    });
    return cache;
}

void set_rtl_notice_program(const std::string& program) { notice_program() = program; }

}  // namespace cdvp
