#include "sw/study/sweep_csv.h"

#include <sstream>

#include "models/common/user_text.h"

namespace cdvp {

std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

CsvRecords::CsvRecords(std::istream& in, std::string label, std::size_t max_record_bytes)
    : in_(in), label_(std::move(label)), max_bytes_(max_record_bytes) {}

bool CsvRecords::next(std::vector<std::string>& fields) {
    fields.clear();
    line_ = next_line_;
    std::string field;
    bool quoted = false, any = false;
    std::size_t bytes = 0;
    for (int c; (c = in_.get()) != std::istream::traits_type::eof();) {
        any = true;
        if (++bytes > max_bytes_) {
            throw InputError(label_ + ":" + std::to_string(line_) + ": a row longer than " + std::to_string(max_bytes_) +
                             " bytes; expected a row of a sweep table");
        }
        if (c == '\n') ++next_line_;
        if (quoted) {
            if (c == '"' && in_.peek() == '"') {
                field += '"';
                in_.get();
            } else if (c == '"') {
                quoted = false;
            } else {
                field += static_cast<char>(c);
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields.push_back(std::move(field));
            field.clear();
        } else if (c == '\n') {
            fields.push_back(std::move(field));
            complete_ = true;
            return true;
        } else if (c != '\r') {
            field += static_cast<char>(c);
        }
    }
    if (!any) return false;
    if (quoted) throw InputError(label_ + ":" + std::to_string(line_) + ": a quoted field is not closed");
    fields.push_back(std::move(field));
    complete_ = false;
    return true;
}

std::vector<std::vector<std::string>> parse_csv(const std::string& text, const std::string& label) {
    std::istringstream in(text);
    CsvRecords records(in, label, text.size() + 1);
    std::vector<std::vector<std::string>> lines;
    for (std::vector<std::string> fields; records.next(fields);) lines.push_back(fields);
    return lines;
}

}  // namespace cdvp
