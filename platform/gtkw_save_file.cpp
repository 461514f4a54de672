#include "platform/gtkw_save_file.h"

#include <cmath>

namespace cdvp {

namespace {

// SystemC's VCD writer puts every signal under a top scope of this name, and
// GTKWave looks a save file's signals up by their whole path.

// GTKWave's trace flags (its analyzer.h), written in hex after '@'.
constexpr uint64_t kHex = 1u << 1, kDecimal = 1u << 2, kBinary = 1u << 3, kRightJustify = 1u << 5,
                   kBlank = 1u << 9, kTranslated = 1u << 13, kGroupBegin = 1u << 23, kGroupEnd = 1u << 24;

uint64_t flags_for(WaveFormat format) {
    switch (format) {
        case WaveFormat::kBit:
        case WaveFormat::kBinary: return kRightJustify | kBinary;
        case WaveFormat::kDecimal: return kRightJustify | kDecimal;
        case WaveFormat::kHex: return kRightJustify | kHex;
        case WaveFormat::kNamed: return kRightJustify | kDecimal | kTranslated;  // the filter's keys are decimal
    }
    return kRightJustify | kHex;
}

// The pixels of the window that are not wave pane: scroll bars, borders,
// the collapsed signal search tree. Taken generously, so the view fits.
constexpr int kWindowChrome = 72;
// GTKWave's zoom: a step of 1 halves the time per pixel; at zoom 0 a frame
// of 200 pixels spans one time unit.
constexpr double kPixelsPerZoomFrame = 200.0;

// The view with a little room on both sides, so edges at its ends show.
WaveView padded(const WaveView& view) {
    WaveView room = view;
    const uint64_t margin = (view.end_fs - view.begin_fs) / 50;
    room.begin_fs = view.begin_fs > margin ? view.begin_fs - margin : 0;
    room.end_fs = view.end_fs + margin;
    return room;
}

void write_view(std::ostream& out, const WaveView& framed) {
    const WaveView view = padded(framed);
    out << "[timestart] " << view.begin_fs << '\n'
        << "[size] " << kSaveFileWindowWidth << ' ' << kSaveFileWindowHeight << '\n'
        << "[signals_width] " << kSaveFileSignalsWidth << '\n'
        << "[sst_expanded] 0\n";
    if (view.end_fs == view.begin_fs) return;
    // The zoom, the primary marker, then GTKWave's 26 named markers A..Z.
    constexpr std::size_t kNamedMarkers = 26;
    out << '*' << viewer_zoom(view.end_fs - view.begin_fs) << ' ';
    if (view.markers.empty()) out << -1;
    else out << view.markers.front().at_fs;
    for (std::size_t k = 0; k < kNamedMarkers; ++k) {
        out << ' ';
        if (k < view.markers.size()) out << view.markers[k].at_fs;
        else out << -1;
    }
    out << '\n';
    for (std::size_t k = 0; k < view.markers.size() && k < kNamedMarkers; ++k) {
        out << "[markername] " << static_cast<char>('A' + k) << view.markers[k].name << '\n';
    }
}

}  // namespace

std::string viewer_name(const TracedSignal& signal, const std::string& top_scope) {
    std::string name = top_scope.empty() ? signal.name : top_scope + "." + signal.name;
    if (signal.format != WaveFormat::kBit) name += "[" + std::to_string(signal.width - 1) + ":0]";
    return name;
}

double viewer_zoom(uint64_t span_fs) {
    const double wave_pixels = kSaveFileWindowWidth - kSaveFileSignalsWidth - kWindowChrome;
    return -std::log2(kPixelsPerZoomFrame * static_cast<double>(span_fs) / wave_pixels);
}

// A group opens with a blank trace flagged as its beginning and its title,
// and closes with one flagged as its end; flags hold until the next '@'.
void write_save_file(std::ostream& out, const SaveFile& save) {
    out << "[dumpfile] \"" << save.dump_path << "\"\n";
    write_view(out, save.view);
    std::string open_group;
    auto close = [&] {
        if (!open_group.empty()) out << '@' << std::hex << (kBlank | kGroupEnd) << std::dec << "\n-" << open_group << '\n';
    };
    std::map<std::string, int> filter_numbers;
    for (const TracedSignal& signal : save.signals) {
        if (signal.group != open_group) {
            close();
            open_group = signal.group;
            out << '@' << std::hex << (kBlank | kGroupBegin) << std::dec << "\n-" << open_group << '\n';
        }
        out << '@' << std::hex << flags_for(signal.format) << std::dec << '\n';
        if (signal.format == WaveFormat::kNamed) {
            const std::string& table = signal.states->table;
            const int number = filter_numbers.emplace(table, static_cast<int>(filter_numbers.size()) + 1).first->second;
            out << '^' << number << ' ' << save.filter_paths.at(table) << '\n';
        }
        out << viewer_name(signal, save.top_scope) << '\n';
    }
    close();
}

void write_translate_filter(std::ostream& out, const StateNames& states) {
    for (std::size_t value = 0; value < states.names.size(); ++value) {
        if (!states.names[value].empty()) out << value << ' ' << states.names[value] << '\n';
    }
}

}  // namespace cdvp
