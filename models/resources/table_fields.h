// The stored tables' CSV (synthesis.csv, timing.csv): a header line, then
// rows of comma-separated fields, no quoting, a "-" where a parameter does
// not apply.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cdvp {

// Calls 'row' with each data row's fields and its place ("ORIGIN:LINE"), after
// checking the header is 'header' and every row has as many fields. Blank
// lines are skipped. Throws std::invalid_argument "ORIGIN:LINE: ..." (and
// whatever 'row' throws).
void read_table(const std::string& csv, const std::string& origin, const std::string& header,
                const std::function<void(const std::vector<std::string>& fields, const std::string& where)>& row);
// What both tables key a row by, their first four columns.
struct TableRowKey {
    std::string family, piece, format;
    uint32_t m = 0;  // 0: not a parameter of the piece
};
TableRowKey table_row_key(const std::vector<std::string>& fields, const std::string& where);
// A whole, non-negative number, or 0 for "-". 'where' ("ORIGIN:LINE") and
// 'column' name the field in the error. Throws std::invalid_argument.
double table_count(const std::string& text, const std::string& where, const char* column);

}  // namespace cdvp
