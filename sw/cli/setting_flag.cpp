#include "sw/cli/setting_flag.h"

#include <stdexcept>

namespace po = boost::program_options;

namespace cdvp {

std::string SettingFlag::name() const {
    if (setting_.value_name.empty()) return "";
    const std::string value = to_text(setting_.default_value());
    if (setting_.type == SettingType::kChoice) return setting_.value_name + " (=" + value + ")";
    // A free text with no default (a path): nothing to show but its name.
    if (setting_.range_text().empty() && value.empty()) return setting_.value_name;
    return setting_.value_name + " (" + setting_.range_text() + "; " + value + ")";
}

void SettingFlag::parse(boost::any& store, const std::vector<std::string>& tokens, bool /*utf8*/) const {
    po::validators::check_first_occurrence(store);  // "--m 2 --m 3" is refused
    // A switch (no value) sets its yes|no choice to the name of true.
    const std::string text = setting_.value_name.empty() ? name_of(true) : tokens.empty() ? std::string() : tokens.front();
    try {
        store = setting_.parse_text(text);
    } catch (const std::invalid_argument& e) {
        // store() fills in the option's name.
        throw po::error_with_option_name(std::string("%canonical_option%: ") + e.what());
    }
}

void SettingFlag::notify(const boost::any& store) const {
    if (store.empty()) return;
    given_->push_back({&setting_, boost::any_cast<SettingValue>(store), {SettingOrigin::Kind::kGiven, "", 0}});
}

}  // namespace cdvp
