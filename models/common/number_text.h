// Numbers typed by a user (a flag's value, a -c override): the whole text
// must be a number of the setting's kind within its range, or it is refused
// with what the user typed ("expected an integer from 1 to 32, got '-1'").
// Unsigned counts never see a minus sign, so nothing wraps around.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

namespace cdvp {

// Throw std::invalid_argument "expected ..., got 'TEXT'".
uint64_t parse_integer_text(const std::string& text, uint64_t min, uint64_t max);
double parse_real_text(const std::string& text, double min, double max);
// How a range reads in help and messages: "1 to 32", "0.001 to 1000".
std::string describe_range(double min, double max);
std::string describe_range(uint64_t min, uint64_t max);
// Whole numbers in full (1048576, not 1.04858e+06); others as %g.
std::string show_number(double value);
// Two figures a message compares ("96.2 MHz is beyond the 96.19 MHz"): each
// to 'decimals' places, or to as many more (up to 12) as it takes for the two
// texts to differ when the values do, so a refusal never reads "96.2 is
// beyond 96.2".
std::pair<std::string, std::string> distinct_figures(double a, double b, int decimals);

}  // namespace cdvp
