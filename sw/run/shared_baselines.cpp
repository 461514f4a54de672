#include "sw/run/shared_baselines.h"

#include <algorithm>
#include <set>

#include "models/common/user_text.h"
#include "platform/settings/setting_values.h"
#include "sw/run/baseline_timing.h"
#include "sw/run/generated_source.h"
#include "sw/run/machine_info.h"
#include "sw/output/digest.h"
#include "sw/run/version.h"

namespace cdvp {

namespace {

// The trace's frames as the run reads them: numbers, ids and coordinates.
std::string frames_digest(FrameSource& source) {
    std::string bytes;
    std::string digests;
    source.rewind();
    while (std::optional<Frame> frame = source.next()) {
        bytes.clear();
        const auto put = [&bytes](const void* data, std::size_t size) {
            bytes.append(static_cast<const char*>(data), size);
        };
        put(&frame->number, sizeof frame->number);
        for (std::size_t k = 0; k < frame->boxes.size(); ++k) {
            if (k < frame->ids.size()) put(&frame->ids[k], sizeof frame->ids[k]);
            put(&frame->boxes[k], sizeof frame->boxes[k]);
        }
        digests += sha256_hex(bytes);
    }
    source.rewind();
    return sha256_hex(digests);
}

}  // namespace

nlohmann::json software_workload(const std::string& scene, FrameSource& source, const SettingValues& values,
                                 const std::vector<std::string>& baselines, const HostTiming& host) {
    const Settings& settings = values.settings();
    nlohmann::json workload = {{"baselines", baselines},
                               {"repeat", settings.run.repeat},
                               {"warmup", settings.run.warmup},
                               {"retime_tries", settings.run.retime_tries},
                               {"cdvp_version", kCdvpVersion},
                               {"cpu_model", read_machine_info().cpu_model},
                               {"host_profile_sha256", host.profile_sha256}};
    // A multi-threaded baseline's time depends on the threads it is given.
    if (std::find(baselines.begin(), baselines.end(), "sap_mt") != baselines.end()) {
        workload["threads"] = baseline_threads(settings.run.threads, settings.host.cores);
    }
    if (scene.empty()) {
        workload["trace_frames_sha256"] = frames_digest(source);
        return workload;
    }
    nlohmann::json scene_settings = nlohmann::json::object();
    for (const Setting* s : values.effective()) {
        // A family's settings go with its own scene only (a pile's key holds no heavy.*).
        const std::string owner = scene_of_setting(*s);
        if (s->section() == "scene" && (owner.empty() || owner == scene || owner == "spheres")) {
            scene_settings[s->name] = to_json(s->get(settings));
        }
    }
    workload["scene"] = scene;
    workload["scene_settings"] = scene_settings;
    return workload;
}

SharedBaselines::SharedBaselines(std::string dir, const std::string& label, nlohmann::json workload,
                                 const std::vector<std::string>& baselines, uint32_t runs, std::size_t frames)
    : dir_(std::move(dir)),
      workload_(std::move(workload)),
      key_(software_timing_key(workload_)),
      max_bytes_(software_timing_max_bytes(runs, frames, baselines.size())) {
    made_.create(dir_, label);
    const std::string path = software_timing_path(dir_, key_);
    std::string sha256;
    timing_ = read_software_timing(path, workload_, sha256, max_bytes_);
    if (!timing_) return;
    const std::set<std::string> wanted(baselines.begin(), baselines.end());
    std::set<std::string> there;
    for (const auto& [name, b] : timing_->baselines) there.insert(name);
    if (there != wanted) throw InputError(path + ": baselines: expected this run's, " + excerpt(nlohmann::json(baselines).dump()));
    for (const auto& [name, b] : timing_->baselines) {
        if (b.cpu_ns.size() != runs || b.cpu_ns.front().size() != frames) {
            throw InputError(path + ": baselines." + name + ".cpu_native_ns: expected " + std::to_string(runs) + " runs of " +
                             std::to_string(frames) + " frames, this run's");
        }
    }
    id_ = software_timing_id(key_, sha256);
}

std::map<std::string, BaselineTime> SharedBaselines::frame(std::size_t index, const HostTiming& host) const {
    std::map<std::string, BaselineTime> times;
    for (const auto& [name, b] : timing_->baselines) {
        BaselineTime& t = times[name];
        t.native_ns = b.cpu_ns[0][index];
        t.wall_native_ns = b.wall_ns[0][index];
        t.host_ns = t.native_ns * host.factor(name);
    }
    return times;
}

void SharedBaselines::take(RunTotals& totals, bool with_first_run) const {
    std::map<std::string, TimingQuality> quality;
    for (const auto& [name, b] : timing_->baselines) {
        for (std::size_t run = with_first_run ? 0 : 1; run < b.cpu_ns.size(); ++run) {
            FrameSamples& cpu = totals.baseline_samples(name);
            FrameSamples& wall = totals.baseline_wall_samples(name);
            if (run > 0) {
                cpu.start_run();
                wall.start_run();
            }
            for (std::size_t k = 0; k < b.cpu_ns[run].size(); ++k) {
                cpu.add(b.cpu_ns[run][k]);
                wall.add(b.wall_ns[run][k]);
            }
        }
        quality[name] = b.quality;
    }
    totals.set_timing_quality(std::move(quality), timing_->retime_tries);
    totals.set_timing_id(id_);
}

void SharedBaselines::complete(RunTotals& totals) const { take(totals, false); }

void SharedBaselines::publish(RunTotals& totals, uint32_t retime_tries) {
    SoftwareTiming own;
    own.workload = workload_;
    own.retime_tries = retime_tries;
    for (const auto& [name, quality] : totals.timing_quality()) {
        SoftwareTiming::Baseline& b = own.baselines[name];
        b.cpu_ns = totals.baseline_samples(name).run_values();
        b.wall_ns = totals.baseline_wall_samples(name).run_values();
        b.quality = quality;
    }
    const std::optional<std::string> added = publish_software_timing(dir_, own);
    made_.keep();  // it holds a timing now, this run's or another's
    if (added) {
        id_ = software_timing_id(key_, *added);
        totals.set_timing_id(id_);
        return;
    }
    // Another point of the workload was first: its timing is the one.
    std::string sha256;
    timing_ = read_software_timing(software_timing_path(dir_, key_), workload_, sha256, max_bytes_);
    if (!timing_) throw InputError(software_timing_path(dir_, key_) + ": added by another run, then gone");
    id_ = software_timing_id(key_, sha256);
    totals.clear_baselines();
    take(totals, true);
}

}  // namespace cdvp
