// A dedicated flag of `cdvp run` for one setting of the table
// (platform/settings/settings.h): its range, default and help come from the setting,
// its value is checked by the setting's own parser ("--m: expected an
// integer from 1 to 32, got '-4294967295'"), and a flag given is a layer
// over the defaults, the preset, the config file and -c.
#pragma once

#include <boost/program_options.hpp>

#include <string>
#include <vector>

#include "platform/settings/setting_values.h"

namespace cdvp {

class SettingFlag : public boost::program_options::value_semantic {
public:
    SettingFlag(const Setting& setting, std::vector<Assignment>* given) : setting_(setting), given_(given) {}

    std::string name() const override;
    // A switch (a setting without a value name) takes no value.
    unsigned min_tokens() const override { return setting_.value_name.empty() ? 0 : 1; }
    unsigned max_tokens() const override { return setting_.value_name.empty() ? 0 : 1; }
    bool is_composing() const override { return false; }
    bool is_required() const override { return false; }
    void parse(boost::any& store, const std::vector<std::string>& tokens, bool utf8) const override;
    bool apply_default(boost::any&) const override { return false; }
    void notify(const boost::any& store) const override;

private:
    const Setting& setting_;
    std::vector<Assignment>* given_;
};

}  // namespace cdvp
