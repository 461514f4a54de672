#include "sw/output/output_set.h"

#include <unistd.h>

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "sw/output/output_cleanup.h"
#include "sw/scene/scene.h"

namespace cdvp {

namespace {

std::string quoted(const std::string& label, const std::string& path) { return label + " '" + path + "'"; }

}  // namespace

void OutputSet::add_input(std::string label, std::string path) {
    inputs_.push_back({std::move(label), std::move(path), "", false});
}

std::size_t OutputSet::add_output(std::string label, std::string path, std::string suffix, bool open_stream) {
    if (!files_.empty()) throw std::logic_error("OutputSet::add_output after open()");
    outputs_.push_back({std::move(label), std::move(path), std::move(suffix), open_stream});
    return outputs_.size() - 1;
}

void OutputSet::add_standard_output(std::string label) { stdout_label_ = std::move(label); }

void OutputSet::set_standard_output(std::string text) { stdout_text_ = std::move(text); }

namespace {

// What an output writes to, for the sameness checks. A device, FIFO or pipe
// is written, never replaced, so it may be named twice; a regular file
// reached through a descriptor (/dev/fd/3 3>>FILE, stdout >>FILE) is
// appended to, so it must be no input, and no other output unless both
// write through the same descriptor, one after the other.
struct Written {
    std::string name;  // label and path, for messages
    FileIdentity id;
    bool checked;    // a regular file (or a new one)
    int descriptor;  // >= 0: written through this process's descriptor
};

// Whether an output writes to standard output itself ("-", /dev/stdout):
// standard output is then a data stream, and the summary is not mixed in.
bool writes_standard_output(const std::vector<Written>& written) {
    struct stat status {};
    const bool open_at_start = !standard_descriptor_was_closed(STDOUT_FILENO) && fstat(STDOUT_FILENO, &status) == 0;
    return std::any_of(written.begin(), written.end(), [&](const Written& w) {
        return w.descriptor == STDOUT_FILENO || (open_at_start && w.descriptor >= 0 && w.id.exists &&
                                                 w.id.device == status.st_dev && w.id.inode == status.st_ino);
    });
}

Written standard_output_written(const std::string& label) {
    if (standard_descriptor_was_closed(STDOUT_FILENO)) {
        throw InputError(label + ": closed when cdvp started; expected it open (or --quiet)");
    }
    struct stat status {};
    if (fstat(STDOUT_FILENO, &status) != 0) throw InputError(label + ": " + std::strerror(errno));
    FileIdentity id;
    id.path = "/dev/stdout";
    id.exists = true;
    id.device = status.st_dev;
    id.inode = status.st_ino;
    return {label, id, S_ISREG(status.st_mode) != 0, STDOUT_FILENO};
}

}  // namespace

std::vector<OutputTarget> OutputSet::resolve_targets() const {
    std::vector<OutputTarget> targets;
    for (const Declared& out : outputs_) {
        if (out.path.empty()) throw InputError(out.label + ": expected a file path, got ''");
        try {
            targets.push_back(resolve_output_target(out.path));
        } catch (const InputError& e) {
            throw InputError(out.label + ": " + e.what());
        }
    }
    return targets;
}

void OutputSet::open() {
    const std::vector<OutputTarget> targets = resolve_targets();
    std::vector<Written> written;
    for (std::size_t k = 0; k < outputs_.size(); ++k) {
        const bool direct = targets[k].kind == OutputTarget::Kind::kDirect;
        written.push_back({quoted(outputs_[k].label, outputs_[k].path), identity_of(targets[k]),
                           !direct || S_ISREG(targets[k].status.st_mode), direct ? targets[k].descriptor : -1});
    }
    if (stdout_label_ && writes_standard_output(written)) stdout_label_.reset();
    if (stdout_label_) written.push_back(standard_output_written(*stdout_label_));
    std::vector<FileIdentity> input_ids;  // only needed against something written
    if (!written.empty()) {
        for (const Declared& in : inputs_) input_ids.push_back(identity_of_input(in.path));
    }
    for (std::size_t k = 0; k < written.size(); ++k) {
        if (!written[k].checked) continue;
        for (std::size_t i = 0; i < inputs_.size(); ++i) {
            if (written[k].id == input_ids[i]) {
                const bool appended = outputs_.size() <= k || targets[k].kind == OutputTarget::Kind::kDirect;
                throw InputError(written[k].name + " is the input " + quoted(inputs_[i].label, inputs_[i].path) +
                                 (appended ? "; an output never writes into an input"
                                           : "; an output never replaces an input"));
            }
        }
        for (std::size_t j = 0; j < k; ++j) {
            const bool one_descriptor = written[j].descriptor >= 0 && written[j].descriptor == written[k].descriptor;
            if (written[j].checked && !one_descriptor && written[j].id == written[k].id) {
                throw InputError(written[k].name + " is the same file as " + written[j].name +
                                 "; give each output its own file");
            }
        }
    }
    std::deque<OutputFile> files;
    for (const Declared& out : outputs_) {
        try {
            files.emplace_back(out.path, out.suffix, out.open_stream);
        } catch (const InputError& e) {
            throw InputError(out.label + ": " + e.what());
        }
    }
    files_ = std::move(files);
}

void OutputSet::commit() {
    if (const std::optional<OutputFailure> failure = try_commit()) failure->raise();
}

namespace {

// Writes all of 'text' to 'fd'. 0 or errno.
int write_all(int fd, const std::string& text) {
    for (std::size_t done = 0; done < text.size();) {
        const ssize_t put = write(fd, text.data() + done, text.size() - done);
        if (put < 0 && errno != EINTR) return errno;
        if (put > 0) done += static_cast<std::size_t>(put);
    }
    return 0;
}

}  // namespace

void OutputFailure::raise() const {
    if (system()) throw SystemError(message);
    throw InputError(message);
}

std::optional<OutputFailure> OutputSet::try_commit() noexcept {
    const auto failure = [this](std::size_t k, int err) {
        return std::optional<OutputFailure>(OutputFailure{outputs_[k].label + ": " + files_[k].error_message(err), err});
    };
    for (std::size_t k = 0; k < files_.size(); ++k) {
        if (const int err = files_[k].try_finish()) return failure(k, err);
    }
    // Devices, FIFOs and standard output cannot be rolled back, so they go
    // first: a failure there leaves every regular file untouched. Signals
    // stay deliverable meanwhile: opening a FIFO waits for a reader and a
    // pipe may be full, and a signal must still end the run (the handler
    // removes the temporaries, so no regular output appears).
    for (std::size_t k = 0; k < files_.size(); ++k) {
        if (files_[k].target().kind != OutputTarget::Kind::kDirect) continue;
        std::string unused;
        if (const int err = files_[k].try_publish(unused)) return failure(k, err);
    }
    if (stdout_label_ && !stdout_text_.empty()) {
        if (const int err = write_all(STDOUT_FILENO, stdout_text_)) {
            return OutputFailure{*stdout_label_ + ": cannot write: " + std::strerror(err), err};
        }
    }
    // The renames and their rollback are never cut short: a signal arriving
    // meanwhile is delivered once every output is in place (or none is).
    CleanupSignalsBlocked blocked;
    struct Published {
        std::string path, backup;
    };
    std::vector<Published> published;
    for (std::size_t k = 0; k < files_.size(); ++k) {
        OutputFile& file = files_[k];
        if (file.target().kind == OutputTarget::Kind::kDirect) continue;
        const std::string path = file.target().path;
        std::string backup;
        if (const int err = file.try_publish(backup)) {
            for (auto it = published.rbegin(); it != published.rend(); ++it) {
                if (it->backup.empty()) {
                    unlink(it->path.c_str());
                } else {
                    std::rename(it->backup.c_str(), it->path.c_str());
                }
            }
            return failure(k, err);
        }
        published.push_back({path, std::move(backup)});
    }
    for (const Published& p : published) {
        if (!p.backup.empty()) unlink(p.backup.c_str());
    }
    return std::nullopt;
}

}  // namespace cdvp
