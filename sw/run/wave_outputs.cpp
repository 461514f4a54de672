#include "sw/run/wave_outputs.h"

#include <sys/wait.h>

#include <filesystem>

#include "models/common/user_text.h"
#include "platform/gtkw_save_file.h"
#include "platform/virtual_board.h"
#include "sw/output/child_process.h"

namespace cdvp {

namespace {

constexpr const char* kFstConverter = "vcd2fst";

// The path without its dump extension: "w.vcd" or "w.fst" -> "w".
std::string dump_stem(const std::string& path) {
    for (const char* extension : {".vcd", ".fst"}) {
        const std::size_t size = std::char_traits<char>::length(extension);
        if (path.size() > size && path.compare(path.size() - size, size, extension) == 0) {
            return path.substr(0, path.size() - size);
        }
    }
    return path;
}

// A dump to a device or descriptor has no directory to put a save file in.
bool has_save_file(const std::string& path) { return path != "-" && path.rfind("/dev/", 0) != 0; }

std::string filter_path(const std::string& dump_path, const StateNames& table) {
    return dump_stem(dump_path) + "." + table.table + "-states.txt";
}

std::string absolute(const std::string& path) { return std::filesystem::absolute(path).string(); }

}  // namespace

DumpFormat parse_dump_format(const std::string& text, const SettingNames& names) {
    if (text == "vcd") return DumpFormat::kVcd;
    const std::string label = names.input("vcd-format");
    if (text != "fst") throw InputError(label + ": expected vcd or fst, got '" + excerpt(text) + "'");
    if (!find_program(kFstConverter)) throw InputError(label + " fst: needs vcd2fst on PATH (Debian's gtkwave package)");
    return DumpFormat::kFst;
}

void WaveOutputs::declare(OutputSet& files, const std::string& path, DumpFormat format, const std::string& label,
                          const std::vector<const StateNames*>& tables) {
    path_ = path;
    format_ = format;
    tables_ = tables;
    // SystemC names the VCD itself (base + ".vcd"); vcd2fst writes the FST over its temporary.
    dump_index_ = format == DumpFormat::kVcd ? files.add_output(label, path, ".vcd", false)
                                             : files.add_output(label, path, "", false);
    if (!has_save_file(path)) return;
    save_index_ = files.add_output(label + " (its GTKWave save file)", dump_stem(path) + ".gtkw");
    for (const StateNames* table : tables_) {
        filter_indices_[table->table] =
            files.add_output(label + " (its " + table->table + " state names)", filter_path(path, *table));
    }
}

void WaveOutputs::bind(OutputSet& files) {
    files_ = &files;
    if (!dump_index_) return;
    dump_ = &files.file(*dump_index_);
    // The scratch VCD sits beside the FST, where the run's other temporaries
    // are, and is removed on every way out (it is never published).
    if (format_ == DumpFormat::kFst) scratch_vcd_.emplace(dump_->final_path(), ".vcd", false);
}

std::string WaveOutputs::trace_base() const {
    if (dump_ == nullptr) return {};
    const std::string& vcd = scratch_vcd_ ? scratch_vcd_->temp_path() : dump_->temp_path();
    return vcd.substr(0, vcd.size() - 4);  // SystemC appends ".vcd"
}

std::optional<std::string> WaveOutputs::finish(const VirtualBoard& platform) {
    if (dump_ == nullptr) return std::nullopt;
    if (scratch_vcd_) {
        CapturedOutput errors("cdvp-vcd2fst-errors");
        ChildStreams streams;
        streams.out = streams.err = errors.fd();
        const int status = run_child({kFstConverter, scratch_vcd_->temp_path(), dump_->temp_path()}, streams);
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            return "--vcd " + excerpt(path_) + ": vcd2fst failed: " + printable(errors.text(4096));
        }
    }
    if (!save_index_) return std::nullopt;
    std::map<std::string, std::string> filter_paths;
    for (const StateNames* table : tables_) {
        write_translate_filter(files_->file(filter_indices_.at(table->table)).stream(), *table);
        filter_paths[table->table] = absolute(filter_path(path_, *table));
    }
    platform.write_gtkw(files_->file(*save_index_).stream(), absolute(path_), filter_paths);
    return std::nullopt;
}

}  // namespace cdvp
