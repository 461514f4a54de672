// Variants of the board RTL that the binary does not hold, compiled on first
// use and kept in a per-user cache: Verilator and the C++ compiler cdvp was
// built with turn the RTL kit (rtl_kit.h) into a shared object exposing one C
// entry point (rtl_model_entry.cpp.in), which later runs load with dlopen
// without compiling.
//
// An entry is a directory DIR/NAME-KEY: NAME names the variant
// (RtlVariant::name), KEY is the first 16 hex digits of the SHA-256 of what
// the model is made from: its parameters, cdvp's version, git commit,
// compiler and flags, Verilator's arguments and every kit file's digest
// (rtl_model_key_text), so that a changed RTL or build never reuses a stale
// model. Its stamp.txt, written last, records the shared object's size and
// digest; an entry whose stamp, object or entry point does not check out is
// damaged and compiled again. Two processes that want one variant at once
// take turns on NAME-KEY.lock: the first compiles into a temporary directory
// beside the entry and renames it into place, the other waits and loads it.
#pragma once

#include <functional>
#include <string>

#include "models/rtl_engine/rtl_board.h"
#include "models/rtl_engine/rtl_kit.h"
#include "models/rtl_engine/rtl_variant.h"

namespace cdvp {

// The text an entry's key digests (one "what value" line each); throws
// InputError when a kit file cannot be read.
std::string rtl_model_key_text(const RtlVariant& variant, const RtlBuild& build, const RtlKit& kit);

class RtlModelCache {
public:
    // A line of progress (compiling, waiting for another process), without
    // the program's name.
    using Notice = std::function<void(const std::string& line)>;

    RtlModelCache(std::string directory, const RtlBuild& build, const RtlKit& kit, Notice notice);

    // $CDVP_RTL_CACHE if set and not empty, else $XDG_CACHE_HOME/cdvp/rtl
    // when XDG_CACHE_HOME is an absolute path (a relative one is ignored, as
    // the XDG Base Directory rules say), else $HOME/.cache/cdvp/rtl when HOME
    // is one; empty when none is (user_base_directory): no cache.
    static std::string default_directory();

    // The entry point of the variant's model: loaded from the cache, or
    // compiled into it first. Throws InputError or SystemError, one line:
    // no cache (an empty directory: which variable to set), a relative
    // CDVP_RTL_CACHE, an entry (its directory, stamp.txt or model.so) that
    // is not the user's own or is writable by group or others (it is never
    // loaded), a cache that cannot be created, a tool missing, a failed
    // compile (with its log's path). A compiled entry is made writable by
    // its owner alone.
    RtlBoardMaker load(const RtlVariant& variant);

private:
    std::string directory_;
    const RtlBuild& build_;
    const RtlKit& kit_;
    Notice notice_;
};

// The process's cache: default_directory(), the binary's build and kit, its
// notices on standard error as "PROGRAM: line".
RtlModelCache& process_rtl_model_cache();
// The program named in those notices ("cdvp run"; "cdvp" until set).
void set_rtl_notice_program(const std::string& program);

}  // namespace cdvp
