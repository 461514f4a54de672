#include "sw/python/keywords.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "models/common/user_text.h"
#include "platform/settings/board_preset.h"
#include "platform/settings/config_file.h"
#include "platform/settings/settings.h"
#include "sw/python/python_names.h"
#include "sw/run/run_arguments.h"
#include "sw/study/sweep_grid.h"
#include "sw/study/sweep_inputs.h"
#include "sw/study/sweep_manifest.h"
#include "sw/study/sweep_state.h"

namespace py = pybind11;

namespace cdvp {

namespace {

// A Python str as UTF-8 with Python's error handler `errors` for a lone
// surrogate (a name made from bytes that are no UTF-8).
std::string encoded(py::handle text, const char* errors) {
    PyObject* bytes = PyUnicode_AsEncodedString(text.ptr(), "utf-8", errors);
    if (bytes == nullptr) throw py::error_already_set();
    return py::reinterpret_steal<py::bytes>(bytes);
}

// ... for a message: a lone surrogate as its escape (\udcff).
std::string utf8(py::handle text) { return encoded(text, "backslashreplace"); }

std::string type_name(py::handle value) { return utf8(py::type::handle_of(value).attr("__name__")); }

// A name the user gave (a keyword, a setting's, an axis's) for a message, as
// Python shows it: quoted, a NUL or another control character escaped
// ('obj\x00ects'), never cut short.
std::string quoted(py::handle name) { return utf8(py::repr(name)); }

[[noreturn]] void wrong_type(const std::string& label, const std::string& expected, py::handle value) {
    throw py::type_error(label + ": expected " + expected + ", got " + type_name(value));
}

// The name to look up: a str, as UTF-8 (a lone surrogate kept as its three
// bytes, so that such a name matches none and is refused by its quoted form).
std::string key_of(py::handle name, const std::string& label, const std::string& names) {
    if (!py::isinstance<py::str>(name)) wrong_type(label, names + " as str", name);
    return encoded(name, "surrogatepass");
}

// True or False: Python's bool, or numpy's, which is no int (though it has
// __index__ and __float__) and is refused where a number is expected.
bool is_boolean(py::handle value) {
    if (py::isinstance<py::bool_>(value)) return true;
    const py::dict modules = py::module_::import("sys").attr("modules");
    return modules.contains("numpy") && py::isinstance(value, modules["numpy"].attr("bool_"));
}

std::string without_nul(std::string text, const std::string& label) {
    if (text.find('\0') != std::string::npos) throw InputError(label + ": a value may not hold a NUL character");
    return text;
}

// A text as the file system has it: str (non-UTF-8 names from os.listdir
// by their escapes), bytes, or os.PathLike, through os.fsencode.
std::string path_of(py::handle value, const std::string& label) {
    if (!py::isinstance<py::str>(value) && !py::isinstance<py::bytes>(value) && !py::hasattr(value, "__fspath__")) {
        wrong_type(label, "a str, bytes or os.PathLike", value);
    }
    const py::bytes encoded = py::module_::import("os").attr("fsencode")(value);
    return without_nul(encoded, label);
}

std::string text_of(py::handle value, const std::string& label) {
    if (!py::isinstance<py::str>(value)) wrong_type(label, "a str", value);
    return path_of(value, label);
}

bool is_list(py::handle value) { return py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value); }

// A str, or a list or tuple of them.
std::vector<std::string> texts_of(py::handle value, const std::string& label) {
    if (py::isinstance<py::str>(value)) return {text_of(value, label)};
    if (!is_list(value)) wrong_type(label, "a str or a list of str", value);
    std::vector<std::string> texts;
    for (py::handle item : value) texts.push_back(text_of(item, label));
    return texts;
}

// An int, or anything with __index__ (numpy.int64), but no bool.
py::int_ int_of(py::handle value, const std::string& label) {
    if (is_boolean(value) || !PyIndex_Check(value.ptr())) wrong_type(label, "an int", value);
    PyObject* number = PyNumber_Index(value.ptr());
    if (number == nullptr) throw py::error_already_set();
    return py::reinterpret_steal<py::int_>(number);
}

SettingValue count_value(const Setting& s, py::handle value, const std::string& label) {
    const py::int_ number = int_of(value, label);
    const unsigned long long count = PyLong_AsUnsignedLongLong(number.ptr());
    if (PyErr_Occurred() != nullptr) {  // below 0 or above 2^64 - 1
        PyErr_Clear();
        return s.from_number(number < py::int_(0) ? -1.0 : HUGE_VAL, utf8(py::str(static_cast<py::handle>(number))));
    }
    return s.from_count(count);
}

SettingValue real_value(const Setting& s, py::handle value, const std::string& label) {
    if (is_boolean(value) ||
        !(PyFloat_Check(value.ptr()) || PyIndex_Check(value.ptr()) || py::hasattr(value, "__float__"))) {
        wrong_type(label, "a number", value);
    }
    const double number = PyFloat_AsDouble(value.ptr());
    if (PyErr_Occurred() != nullptr) throw py::error_already_set();
    return s.from_number(number, utf8(py::str(value)));
}

SettingValue choice_value(const Setting& s, py::handle value, const std::string& label) {
    if (is_yes_no(s)) {
        if (!py::isinstance<py::bool_>(value)) wrong_type(label, "True or False", value);
        return s.from_string(value.cast<bool>() ? "yes" : "no");
    }
    return s.from_string(text_of(value, label));
}

// A text: a file's name (a flag's FILE) as a path; a number (a flag's N,
// run.pin_cpu) as a str or an int; any other a str.
SettingValue text_value(const Setting& s, py::handle value, const std::string& label) {
    if (s.value_name == "FILE") return s.from_string(path_of(value, label));
    if (s.value_name == "N" && !is_boolean(value) && PyIndex_Check(value.ptr())) {
        return s.from_string(utf8(py::str(value)));
    }
    if (!py::isinstance<py::str>(value)) wrong_type(label, s.value_name == "N" ? "a str or an int" : "a str", value);
    return s.from_string(text_of(value, label));
}

// A setting's value from Python, of its type and no other (docs/python.md:
// keywords are typed values).
SettingValue typed_value(const Setting& s, py::handle value, const std::string& label) {
    try {
        switch (s.type) {
            case SettingType::kCount:
                return count_value(s, value, label);
            case SettingType::kReal:
                return real_value(s, value, label);
            case SettingType::kChoice:
                return choice_value(s, value, label);
            case SettingType::kText:
                return text_value(s, value, label);
        }
    } catch (const std::invalid_argument& e) {
        throw InputError(label + ": " + e.what());
    }
    throw std::logic_error("a setting of no type");
}

Assignment given(const Setting& s, py::handle value, const std::string& label) {
    return {&s, typed_value(s, value, label), {SettingOrigin::Kind::kGiven, "", 0}};
}

std::string keyword_label(const std::string& key) { return key + "="; }

// The keywords of the settings that have one (m, objects, quantum_ns, ...).
std::vector<std::string> setting_keywords() {
    std::vector<std::string> keywords;
    for (const Setting& setting : settings_table()) {
        if (!setting.flag.empty()) keywords.push_back(keyword_of(setting));
    }
    return keywords;
}

void set_frames(RunSpec& spec, FrameInput frames) {
    if (spec.frames) throw InputError("scene= and trace=: give one of them (the run's frames come from it)");
    spec.frames = std::move(frames);
}

// One of cdvp.run's keywords: an input that is no setting, or a setting's.
void set_keyword(RunSpec& spec, py::handle name, py::handle value, const std::string& function) {
    const std::string key = key_of(name, function, "keywords");
    const std::string label = keyword_label(key);
    if (key == "board") {
        spec.settings.board = path_of(value, label);
    } else if (key == "config") {
        spec.settings.config = path_of(value, label);
    } else if (key == "scene") {
        set_frames(spec, SceneFrames{text_of(value, label)});
    } else if (key == "trace") {
        set_frames(spec, TraceFrames{path_of(value, label)});
    } else if (key == "baseline") {
        spec.baselines = py::isinstance<py::str>(value) ? comma_list(text_of(value, label)) : texts_of(value, label);
    } else if (key == "inject") {
        for (std::string& fault : texts_of(value, label)) spec.faults.push_back(std::move(fault));
    } else if (key == "software_timings") {
        spec.software_timings = path_of(value, label);
    } else if (key == "report" || key == "pairs_out" || key == "vcd" || key == "vcd_frames" || key == "vcd_format") {
        throw InputError(label + ": the module's own: the report comes back as a Report (its pairs with pairs=True); "
                                 "waveforms are the command line's (cdvp run --vcd)");
    } else if (const Setting* s = setting_of_keyword(key)) {
        spec.settings.given.push_back(given(*s, value, label));
    } else {
        std::vector<std::string> keywords{"board", "config", "scene", "trace", "baseline", "inject", "software_timings"};
        for (const std::string& keyword : setting_keywords()) keywords.push_back(keyword);
        const std::optional<std::string> nearest = nearest_name(key, keywords);
        throw py::type_error(function + "() got an unexpected keyword argument " + quoted(name) + " (" +
                             (nearest ? "the nearest is '" + *nearest + "'; " : "") +
                             "any setting goes in settings={NAME: VALUE})");
    }
}

void set_settings(RunSpec& spec, py::handle settings) {
    if (settings.is_none()) return;
    if (!py::isinstance<py::dict>(settings)) wrong_type("settings", "a dict of setting name -> value", settings);
    for (const auto& [name, value] : py::reinterpret_borrow<py::dict>(settings)) {
        const std::string key = key_of(name, "settings", "setting names");
        const std::string label = "settings[" + quoted(name) + "]";
        const Setting* s = find_setting(key);
        if (s == nullptr) {
            const std::optional<std::string> nearest = nearest_name(key, setting_names());
            throw InputError(label + ": no setting has this name" +
                             (nearest ? "; the nearest is '" + *nearest + "'" : "") + " (cdvp.settings() lists them)");
        }
        if (!value.is_none()) spec.settings.given.push_back(given(*s, value, label));
    }
}

// A sweep's axis: a setting (by its dotted name or keyword) or an input
// (board, trace, scene, config), with its values checked before any point runs.
Axis axis_of(const std::string& name, py::handle values, const std::string& label) {
    Axis axis{name, {}};
    const Setting* s = find_setting(name);
    if (s == nullptr) s = setting_of_keyword(name);
    const bool input = name == "board" || name == "trace" || name == "scene" || name == "config";
    if (s == nullptr && !input) {
        std::vector<std::string> names = setting_names();
        for (const std::string& keyword : setting_keywords()) names.push_back(keyword);
        const std::optional<std::string> nearest = nearest_name(name, names);
        throw InputError(label + ": no setting or input has this name" +
                         (nearest ? "; the nearest is '" + *nearest + "'" : "") + " (cdvp.settings() lists the settings)");
    }
    axis.key = s != nullptr ? s->name : name;
    axis.flag = s != nullptr ? (s->value_name.empty() ? std::string() : s->flag) : name;
    std::vector<std::string> canonical;
    if (py::isinstance<py::str>(values)) {  // the command line's list text
        axis.values = expand_list(text_of(values, label), label, s != nullptr);
        for (const std::string& value : axis.values) {
            try {
                canonical.push_back(s != nullptr ? to_text(s->parse_text(value)) : value);
            } catch (const std::invalid_argument& e) {
                throw InputError(label + ": " + e.what());
            }
        }
    } else if (is_list(values)) {
        for (py::handle value : values) {
            axis.values.push_back(s != nullptr ? to_text(typed_value(*s, value, label))
                                               : name == "scene" ? text_of(value, label) : path_of(value, label));
            canonical.push_back(axis.values.back());
        }
    } else {
        wrong_type(label, "a list of values or a list's text (\"50:800:x2\")", values);
    }
    if (axis.values.empty()) throw InputError(label + ": expected at least one value");
    if (const auto repeat = first_repeat(canonical)) {
        throw InputError(label + ": '" + excerpt(axis.values[repeat->first]) + "' is the same value as '" +
                         excerpt(axis.values[repeat->second]) + "'; give each value once");
    }
    for (const std::string& value : axis.values) {
        if (axis.key == "board") load_board_preset(value, label);
        if (axis.key == "config") read_config_file(value);
    }
    return axis;
}

bool flag_of(const py::dict& own, const char* key, bool otherwise) {
    if (!own.contains(key) || own[key].is_none()) return otherwise;
    const py::object value = own[key];
    if (!py::isinstance<py::bool_>(value)) wrong_type(keyword_label(key), "True or False", value);
    return value.cast<bool>();
}

unsigned jobs_of(py::handle value) {
    const py::int_ jobs = int_of(value, "jobs=");
    if (jobs < py::int_(1) || jobs > py::int_(kMaxJobs)) {
        throw InputError("jobs=: expected a whole number from 1 to " + std::to_string(kMaxJobs) + ", got " +
                         utf8(py::str(static_cast<py::handle>(jobs))));
    }
    return jobs.cast<unsigned>();
}

void read_own(const py::dict& own, SweepSpec& spec) {
    if (!own.contains("out") || own["out"].is_none()) throw py::type_error("cdvp.sweep() needs out, the sweep's directory");
    spec.out_dir = path_of(own["out"], "out=");
    if (spec.out_dir.empty()) throw InputError("out=: expected a directory, got ''");
    while (spec.out_dir.size() > 1 && spec.out_dir.back() == '/') spec.out_dir.pop_back();
    if (own.contains("jobs") && !own["jobs"].is_none()) spec.jobs = jobs_of(own["jobs"]);
    if (own.contains("shard") && !own["shard"].is_none()) spec.shard = parse_shard(text_of(own["shard"], "shard="));
    if (own.contains("record") && !own["record"].is_none()) {
        spec.record = parse_record_mode(text_of(own["record"], "record="), "record=");
    }
    spec.software_timings = software_timings_dir(spec.out_dir);
    if (own.contains("software_timings") && !own["software_timings"].is_none()) {
        std::string dir = path_of(own["software_timings"], "software_timings=");
        if (dir.empty()) throw InputError("software_timings=: expected a directory or 'none', got ''");
        while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
        spec.software_timings = dir == "none" ? std::string() : dir;
        spec.software_timings_given = dir != "none";
    }
    spec.plots = flag_of(own, "plots", true);
    spec.quiet = flag_of(own, "quiet", true);
    spec.rerun_invalid = flag_of(own, "rerun_invalid", false);
    // Set by the package for one task of a sweep spread over an executor (cdvp/_spread.py), never by a user.
    if (own.contains("gathered_into") && !own["gathered_into"].is_none()) {
        const auto [dir, held] = own["gathered_into"].cast<std::pair<std::string, std::vector<std::size_t>>>();
        spec.gathered_into = SweepSpec::GatheredInto{dir, held};
        std::sort(spec.gathered_into->held.begin(), spec.gathered_into->held.end());
    }
}

}  // namespace

RunSpec run_spec_of(const py::dict& keywords, const py::handle& settings, const std::string& function) {
    RunSpec spec;
    spec.settings.names = python_names();
    set_settings(spec, settings);
    for (const auto& [name, value] : keywords) {
        if (!value.is_none()) set_keyword(spec, name, value, function);
    }
    return spec;
}

SweepSpec sweep_spec_of(const py::dict& axes, const py::dict& own, const py::dict& keywords,
                        const py::handle& settings) {
    SweepSpec spec;
    spec.program = "cdvp.sweep";
    read_own(own, spec);
    std::set<std::string> axis_keys;
    const auto add_axis = [&](const std::string& key, py::handle values, const std::string& label) {
        Axis axis = axis_of(key, values, label);
        if (!axis_keys.insert(axis.key).second) {
            throw InputError(label + ": " + axis.key + " is an axis already; give it once");
        }
        spec.axes.push_back(std::move(axis));
    };
    for (const auto& [name, values] : axes) {
        add_axis(key_of(name, "axes", "axis names"), values, "axes[" + quoted(name) + "]");
    }
    // board, scene, trace and fidelity are axes of the sweep, as on the command line.
    py::dict point_keywords;
    for (const auto& [name, value] : keywords) {
        const std::string key = key_of(name, "cdvp.sweep", "keywords");
        if (value.is_none()) continue;
        if (key == "board" || key == "scene" || key == "trace" || key == "fidelity") {
            add_axis(key, is_list(value) ? value : py::make_tuple(value), keyword_label(key));
        } else {
            point_keywords[name] = value;
        }
    }
    spec.run = run_spec_of(point_keywords, settings, "cdvp.sweep");
    for (const Assignment& a : spec.run.settings.given) {
        if (axis_keys.count(a.setting->name) != 0) {
            throw InputError(spec.run.settings.names->given(*a.setting) + ": " + a.setting->name +
                             " is an axis of the sweep; give it once");
        }
        if (a.setting->name == "host.profile") {
            const std::string path = to_text(a.value);
            if (!path.empty()) spec.inputs.push_back({"--host-profile", path, path});
        }
    }
    if (spec.run.settings.config) {
        if (axis_keys.count("config") != 0) throw InputError("config=: config is an axis of the sweep; give it once");
        read_config_file(*spec.run.settings.config);  // refused here, naming file and line
        spec.inputs.push_back({"--config", *spec.run.settings.config, *spec.run.settings.config});
    }
    if (spec.run.frames) throw InputError("scene= and trace= of a sweep are axes: give them as keywords or in axes");
    spec.in_process = true;  // analytic points in this process
    name_sweep_inputs(spec);
    return spec;
}

}  // namespace cdvp
