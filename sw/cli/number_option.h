// Every numeric command-line option goes through this one parser: the whole
// token must be a number of the option's type within its range, or the
// option is refused with what the user typed ("--m: expected an integer from
// 1 to 32, got '-4294967295'"). Unsigned types never see a minus sign, so
// nothing wraps around.
#pragma once

#include <boost/program_options.hpp>

#include <limits>
#include <sstream>
#include <string>
#include <type_traits>

#include "models/common/number_text.h"

namespace cdvp {


template <class T>
class NumberValue : public boost::program_options::value_semantic {
    static_assert(std::is_floating_point_v<T> || std::is_unsigned_v<T>, "counts are unsigned, measures real");

public:
    using Wide = std::conditional_t<std::is_floating_point_v<T>, double, uint64_t>;
    NumberValue(T* target, T min, T max, std::string value_name, bool has_default)
        : target_(target), default_(*target), min_(min), max_(max), value_name_(std::move(value_name)),
          has_default_(has_default) {}

    std::string name() const override {
        std::string text = value_name_ + " (" + describe_range(Wide{min_}, Wide{max_});
        if (has_default_) {
            std::ostringstream value;
            value << default_;
            text += "; " + value.str();
        }
        return text + ")";
    }
    unsigned min_tokens() const override { return 1; }
    unsigned max_tokens() const override { return 1; }
    bool is_composing() const override { return false; }
    bool is_required() const override { return false; }
    void parse(boost::any& store, const std::vector<std::string>& tokens, bool /*utf8*/) const override {
        boost::program_options::validators::check_first_occurrence(store);  // "--m 2 --m 3" is refused
        const std::string& text = tokens.empty() ? std::string() : tokens.front();
        try {
            if constexpr (std::is_floating_point_v<T>) {
                store = static_cast<T>(parse_real_text(text, min_, max_));
            } else {
                store = static_cast<T>(parse_integer_text(text, min_, max_));
            }
        } catch (const std::invalid_argument& e) {
            // store() fills in the option's name.
            throw boost::program_options::error_with_option_name(std::string("%canonical_option%: ") + e.what());
        }
    }
    bool apply_default(boost::any& store) const override {
        if (has_default_) store = default_;
        return has_default_;
    }
    void notify(const boost::any& store) const override {
        if (!store.empty()) *target_ = boost::any_cast<T>(store);
    }

private:
    T* target_;
    T default_;
    T min_, max_;
    std::string value_name_;
    bool has_default_;
};

// A numeric option stored in *target; its current value is the default
// unless has_default is false.
template <class T>
NumberValue<T>* number(T* target, T min, T max, const char* value_name, bool has_default = true) {
    return new NumberValue<T>(target, min, max, value_name, has_default);
}

}  // namespace cdvp
