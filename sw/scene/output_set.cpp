#include "sw/scene/output_set.h"

#include <unistd.h>

#include <cstdio>
#include <stdexcept>
#include <utility>

#include "sw/scene/output_cleanup.h"
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

void OutputSet::open() {
    std::vector<OutputTarget> targets;
    for (const Declared& out : outputs_) {
        if (out.path.empty()) throw InputError(out.label + ": expected a file path, got ''");
        try {
            targets.push_back(resolve_output_target(out.path));
        } catch (const InputError& e) {
            throw InputError(out.label + ": " + e.what());
        }
    }
    std::vector<FileIdentity> input_ids;
    for (const Declared& in : inputs_) input_ids.push_back(identity_of_input(in.path));
    for (std::size_t k = 0; k < outputs_.size(); ++k) {
        if (targets[k].kind == OutputTarget::Kind::kDirect) continue;
        const FileIdentity id = identity_of(targets[k]);
        for (std::size_t i = 0; i < inputs_.size(); ++i) {
            if (id == input_ids[i]) {
                throw InputError(quoted(outputs_[k].label, outputs_[k].path) + " is the input " +
                                 quoted(inputs_[i].label, inputs_[i].path) + "; an output never replaces an input");
            }
        }
        for (std::size_t j = 0; j < k; ++j) {
            if (targets[j].kind != OutputTarget::Kind::kDirect && identity_of(targets[j]) == id) {
                throw InputError(quoted(outputs_[k].label, outputs_[k].path) + " is the same file as " +
                                 quoted(outputs_[j].label, outputs_[j].path) + "; give each output its own file");
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
    if (std::optional<std::string> error = try_commit()) throw InputError(*error);
}

std::optional<std::string> OutputSet::try_commit() noexcept {
    const auto failure = [this](std::size_t k, int err) {
        return std::optional<std::string>(outputs_[k].label + ": " + files_[k].error_message(err));
    };
    for (std::size_t k = 0; k < files_.size(); ++k) {
        if (const int err = files_[k].try_finish()) return failure(k, err);
    }
    CleanupSignalsBlocked blocked;
    struct Published {
        std::string path, backup;
    };
    std::vector<Published> published;
    // Devices cannot be rolled back, so they go first: a failure there
    // leaves every regular file untouched.
    for (bool direct : {true, false}) {
        for (std::size_t k = 0; k < files_.size(); ++k) {
            OutputFile& file = files_[k];
            if ((file.target().kind == OutputTarget::Kind::kDirect) != direct) continue;
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
            if (!direct) published.push_back({path, std::move(backup)});
        }
    }
    for (const Published& p : published) {
        if (!p.backup.empty()) unlink(p.backup.c_str());
    }
    return std::nullopt;
}

}  // namespace cdvp
