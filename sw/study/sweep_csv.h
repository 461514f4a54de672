// RFC 4180 text as sweep.csv holds it: fields quoted when they must be, and
// records read one at a time (a quoted field may hold commas, quotes and line
// ends), so that a table of a million rows is never held as text.
#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace cdvp {

// 'text' as one CSV field: quoted (quotes doubled) when it holds a comma, a
// quote or a line end.
std::string csv_field(const std::string& text);

class CsvRecords {
public:
    // A record longer than 'max_record_bytes' is refused (InputError naming
    // 'label' and its line), so a damaged file cannot grow one without bound.
    static constexpr std::size_t kMaxRecordBytes = std::size_t{1} << 20;
    CsvRecords(std::istream& in, std::string label, std::size_t max_record_bytes = kMaxRecordBytes);

    // The next record into 'fields'; false at the end. A last record without
    // its line end is returned too, with complete() false: a write cut short.
    // Throws InputError naming the label and line on an unclosed quote.
    bool next(std::vector<std::string>& fields);
    // The line the last record started on, from 1.
    std::size_t line() const { return line_; }
    // Whether the last record ended with a line end.
    bool complete() const { return complete_; }

private:
    std::istream& in_;
    std::string label_;
    std::size_t max_bytes_;
    std::size_t line_ = 0;
    std::size_t next_line_ = 1;
    bool complete_ = true;
};

// Splits RFC 4180 text into rows of fields. Throws InputError naming 'label'
// on an unclosed quote.
std::vector<std::vector<std::string>> parse_csv(const std::string& text, const std::string& label);

}  // namespace cdvp
