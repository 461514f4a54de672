#include "sw/cli/help_text.h"
#include "sw/cli/sweep_command.h"

#include <sys/mman.h>
#include <sys/resource.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

#include "sw/cli/exit_status.h"
#include "sw/run/run_budgets.h"
#include "sw/cli/sweep_options.h"
#include "sw/cli/sweep_progress.h"
#include "sw/study/sweep.h"
#include "sw/study/sweep_figures.h"
#include "sw/study/sweep_state.h"

namespace cdvp {

namespace {

// User and system CPU time of the process or of its waited-for children.
std::string cpu_seconds(int who) {
    struct rusage usage {};
    getrusage(who, &usage);
    auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) / 1e6; };
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", seconds(usage.ru_utime) + seconds(usage.ru_stime));
    return text;
}

// Points run here one after another, each allocating its scene, pairs and
// report afresh: glibc would hand the heap's top back to the system after
// every point and fault it in again for the next (with the brk and page
// faults, most of an analytic point's time). Keep it, and keep blocks of up
// to 32 MiB on the heap. Only where the memory goes changes, not the results.
void keep_freed_memory() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    mallopt(M_TOP_PAD, 16 << 20);
    // The heap the memos grow into, as transparent huge pages where the
    // kernel gives them on request: each new scene's frames and pairs are
    // fresh memory, and a first touch costs a fault a 4 KiB page (on a virtual
    // machine, microseconds each), one a 2 MiB page. The pieces are freed at
    // once and stay on the heap (the trim threshold above).
    constexpr std::size_t kPiece = 16 << 20, kPieces = 8;
    void* pieces[kPieces];
    for (void*& piece : pieces) {
        piece = std::malloc(kPiece);
        if (piece == nullptr) continue;
        const std::uintptr_t huge = 2 << 20;
        const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(piece) + huge - 1) & ~(huge - 1);
        const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(piece) + kPiece) & ~(huge - 1);
        if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice only
    }
    for (void* piece : pieces) std::free(piece);
#endif
}

void print_summary(const std::string& out, const SweepOutcome& outcome) {
    std::cout << "cdvp sweep: " << outcome.points << " points in " << table_path(out) << ": " << outcome.ok << " ok, "
              << outcome.refused << " refused, " << outcome.faulted << " faulted"
              << (outcome.failed > 0 ? ", " + std::to_string(outcome.failed) + " failed" : std::string()) << " ("  << outcome.run_now << " run now; CPU time "
              << cpu_seconds(RUSAGE_SELF) << " s in the sweep, " << cpu_seconds(RUSAGE_CHILDREN)
              << " s in its points and plots)\n";
}

int run_sweep_command(SweepSpec spec) {
    spec.trace_limits = spooled_trace_limits();
    if (spec.cdvp_binary.empty()) {
        // Analytic points need no child.
        spec.in_process = true;
        keep_freed_memory();
    }
    SweepProgress progress(!spec.quiet && isatty(STDERR_FILENO));
    const SweepOutcome outcome = run_sweep(spec, &progress);
    const bool recorded = outcome.status == 0 || !outcome.first_failure.empty();
    if (recorded && sweep_stop_signal() == 0 && !spec.quiet) {
        print_summary(spec.out_dir, outcome);
        std::cout << answer_printout(spec.out_dir, outcome.answer);
    }
    if (!outcome.first_failure.empty() && outcome.status == kExitInternal) {
        std::cerr << spec.program << ": " << outcome.failed << (outcome.failed == 1 ? " point" : " points")
                  << " failed inside cdvp (internal error, a cdvp bug), recorded with the reason; the first, "
                  << outcome.first_failure << '\n';
    }
    return outcome.status;
}

}  // namespace

int sweep_command(int argc, char** argv) {
    const int status = exit_status_of("cdvp sweep", [&] {
        const std::optional<SweepSpec> options = parse_sweep_options(argc, argv);
        return options ? run_sweep_command(*options) : print_help("cdvp sweep", sweep_help());
    });
    if (const int signal_number = sweep_stop_signal(); signal_number != 0) {
        // Every temporary is gone (the points removed theirs); end as the
        // signal would have ended the sweep.
        std::signal(signal_number, SIG_DFL);
        raise(signal_number);
        return 128 + signal_number;
    }
    return status;
}

}  // namespace cdvp
