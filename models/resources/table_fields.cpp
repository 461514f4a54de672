#include "models/resources/table_fields.h"

#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace cdvp {

namespace {

// A line's comma-separated fields; a trailing comma gives an empty last one.
std::vector<std::string> fields_of(const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    return fields;
}

}  // namespace

void read_table(const std::string& csv, const std::string& origin, const std::string& header,
                const std::function<void(const std::vector<std::string>& fields, const std::string& where)>& row) {
    const std::size_t columns = fields_of(header).size();
    std::istringstream in(csv);
    std::string line;
    std::size_t number = 0;
    while (std::getline(in, line)) {
        ++number;
        const std::string where = origin + ":" + std::to_string(number);
        if (number == 1) {
            if (line != header) throw std::invalid_argument(where + ": expected the header " + header);
            continue;
        }
        if (line.empty()) continue;
        const std::vector<std::string> fields = fields_of(line);
        if (fields.size() != columns) {
            throw std::invalid_argument(where + ": expected " + std::to_string(columns) + " fields, got " +
                                        std::to_string(fields.size()));
        }
        row(fields, where);
    }
    if (number == 0) throw std::invalid_argument(origin + ": empty; expected the header " + header);
}

TableRowKey table_row_key(const std::vector<std::string>& fields, const std::string& where) {
    return {fields.at(0), fields.at(1), fields.at(2), static_cast<uint32_t>(table_count(fields.at(3), where, "m"))};
}

double table_count(const std::string& text, const std::string& where, const char* column) {
    if (text == "-") return 0;
    char* end = nullptr;
    const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || text[0] == '-' || *end != '\0') {
        throw std::invalid_argument(where + ": " + column + ": expected a whole number or '-', got '" + text + "'");
    }
    return static_cast<double>(value);
}

}  // namespace cdvp
