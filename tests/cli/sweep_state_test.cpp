// A sweep directory's state checked, not trusted, as plain C++: every kind of
// damaged or edited row refused naming file, line and field (or left out to
// run again), rows appended one at a time, the manifest read field by field
// (one writer per directory: directory_lock_test.cpp).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "models/common/user_text.h"
#include "sw/study/child_runs.h"
#include "sw/study/sweep_csv.h"
#include "sw/study/sweep_manifest.h"
#include "sw/run/report_summary.h"
#include "sw/study/sweep_state.h"
#include "sw/study/sweep_table.h"
#include "tests/scene/temp_dir.h"

namespace cdvp {
namespace {

namespace fs = std::filesystem;

// A report of one frame, its summary in the report's own schema.
const std::string kReport = nlohmann::json{{"config", {{"m", 8}}},
                                           {"frames", {{{"frame", 0}, {"total_ns", 100.0}}}},
                                           {"summary", to_json(ReportSummary{})}}
                                .dump();

void write_file(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// A directory holding a sweep of three points: 0 ok, 1 refused, 2 ok.
class SweepDir : public ::testing::Test {
protected:
    SweepDir() : grid_(std::vector<Axis>{{"m", {"1", "2", "4"}}}) { fill(dir()); }
    // Writes the sweep into 'out'.
    void fill(const std::string& out) const {
        fs::create_directories(points_dir(out));
        SweepTable table(grid_);
        for (std::size_t k : {0, 2}) {
            write_file(report_path(out, grid_.point(k)), kReport);
            table.add(k, report_row(grid_, grid_.point(k), kReport, 0.5));
        }
        table.add(1, failed_row(grid_, grid_.point(1), PointStatus::kRefused, "m does not fit", 0.1));
        write_file(table_path(out), table.csv());
    }
    std::string dir() const { return temp_.path().string(); }
    std::string csv() const { return slurp(table_path(dir())); }
    // The table with 'from' replaced by 'to' in it.
    void edit(const std::string& from, const std::string& to) {
        std::string text = csv();
        const std::size_t at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        write_file(table_path(dir()), text.replace(at, from.size(), to));
    }
    // read_table's refusal of the sweep in 'out', or "" when it accepted the file.
    std::string refusal(const Shard& shard = Shard{}, const std::string& out = {}) {
        SweepTable table(grid_);
        try {
            read_table(out.empty() ? dir() : out, grid_, shard, table, false);
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    }
    test::TempDir temp_;
    Grid grid_;
};

TEST_F(SweepDir, ReadsBackEveryRowItWrote) {
    SweepTable table(grid_);
    const TableRead read = read_table(dir(), grid_, Shard{}, table, false);
    EXPECT_EQ(table.size(), 3u);
    EXPECT_FALSE(read.rewrite);
    EXPECT_EQ(table.row(1).get("reason"), "m does not fit");
    EXPECT_EQ(table.csv(), csv()) << "the same table, column for column";
}

TEST_F(SweepDir, AnEditedIndexIsRefusedNamingTheFileLineAndField) {
    edit("m-4,2,", "m-4,1,");
    const std::string why = refusal();
    EXPECT_EQ(why, table_path(dir()) + ":4: field 'point': expected 'm-2' (point 1), got 'm-4'") << why;
    EXPECT_EQ(why.find('\n'), std::string::npos);
}

TEST_F(SweepDir, EveryKindOfRowThatIsNotTheGridsIsRefused) {
    const std::vector<std::pair<std::pair<std::string, std::string>, std::string>> cases{
        {{"m-4,2,", "m-4,7,"}, ":4: field 'index': 7 is not a point of this grid (0 to 2)"},
        {{"m-4,2,", "m-4,x,"}, ":4: field 'index': expected a point's number, got 'x'"},
        {{"m-4,2,", ",2,"}, ":4: field 'point': expected 'm-4' (point 2), got ''"},
        {{",refused,", ",done,"}, ":3: field 'status': expected ok, refused or fault, got 'done'"},
        {{",refused,m does not fit,", ",refused,,"}, ":3: field 'reason': empty; a refused point gives its reason"},
    };
    for (const auto& [change, why] : cases) {
        const std::string before = csv();
        edit(change.first, change.second);
        EXPECT_EQ(refusal(), table_path(dir()) + why);
        write_file(table_path(dir()), before);
    }
}

// A row of another layout (another cdvp version's) is refused before its
// checksum is looked at.
TEST_F(SweepDir, ARowOfAnotherFormatVersionIsRefused) {
    const std::string text = csv();
    const std::size_t line = text.find("m-2,1,refused,m does not fit,");
    ASSERT_NE(line, std::string::npos) << text;
    const std::size_t version = text.find(',', line + std::strlen("m-2,1,refused,m does not fit,")) + 1;
    ASSERT_EQ(text.compare(version, 2, std::to_string(kSweepFormatVersion) + ","), 0) << text.substr(line, 80);
    write_file(table_path(dir()), text.substr(0, version) + "2" + text.substr(version + 1));
    EXPECT_EQ(refusal(), table_path(dir()) + ":3: field 'format_version': expected " +
                             std::to_string(kSweepFormatVersion) + " (a row of this cdvp version), got '2'");
}

TEST_F(SweepDir, AnEditedAxisValueOrMedianOrReportFailsTheChecksum) {
    const std::string before = csv();
    // The row's axis value: m-1's row claiming m = 3.
    std::string text = before;
    const std::size_t line = text.find("m-1,0,ok,");
    const std::size_t value = text.find(",1,", line + 9);
    write_file(table_path(dir()), text.replace(value, 3, ",3,"));
    EXPECT_NE(refusal().find(":2: field 'm': expected '1' (point 0), got '3'"), std::string::npos) << refusal();
    write_file(table_path(dir()), before);
    edit(",100,", ",99,");  // a median
    EXPECT_NE(refusal().find(": field 'checksum': does not match the row and its report"), std::string::npos)
        << refusal();
    write_file(table_path(dir()), before);
    write_file(report_path(dir(), grid_.point(2)), kReport + " ");
    EXPECT_NE(refusal().find(":4: field 'checksum': does not match the row and its report"), std::string::npos)
        << refusal();
    fs::remove(report_path(dir(), grid_.point(2)));
    EXPECT_NE(refusal().find(":4: the point's report " + report_path(dir(), grid_.point(2)) + " cannot be read"),
              std::string::npos)
        << refusal();
}

TEST_F(SweepDir, ARepeatedRowOrARowOfAnotherShardIsRefused) {
    std::string text = csv();
    const std::size_t second = text.find("m-2,1,");
    const std::string row = text.substr(second, text.find('\n', second) - second + 1);
    write_file(table_path(dir()), text + row);
    EXPECT_EQ(refusal(), table_path(dir()) + ":5: field 'index': point 1 is also on line 3");
    write_file(table_path(dir()), text);
    EXPECT_EQ(refusal(Shard{2, 2}), table_path(dir()) + ":2: field 'index': point 0 is not in shard 2/2");
}

TEST_F(SweepDir, AskedToRerunInvalidRowsItLeavesThemOutAndSaysWhich) {
    std::string text = csv();
    const std::size_t second = text.find("m-2,1,");
    write_file(table_path(dir()), text + text.substr(second, text.find('\n', second) - second + 1));
    edit("m-4,2,", "m-4,x,");
    SweepTable table(grid_);
    const TableRead read = read_table(dir(), grid_, Shard{}, table, true);
    EXPECT_EQ(read.invalid.size(), 2u);
    EXPECT_TRUE(read.rewrite);
    EXPECT_TRUE(table.has(0));
    EXPECT_FALSE(table.has(1)) << "neither of two rows for one point is trusted";
    EXPECT_FALSE(table.has(2));
}

TEST_F(SweepDir, ALastRowCutShortIsLeftOutToRunAgain) {
    std::string text = csv();
    write_file(table_path(dir()), text.substr(0, text.size() - 10));
    SweepTable table(grid_);
    const TableRead read = read_table(dir(), grid_, Shard{}, table, false);
    EXPECT_TRUE(read.torn);
    EXPECT_TRUE(read.rewrite);
    EXPECT_EQ(table.size(), 2u);
    EXPECT_FALSE(table.has(2));
}

// However long the --out path, a refusal names the whole file, then the line
// and the field: the file's name is what tells which of the sweep's files it is.
TEST_F(SweepDir, ARefusalUnderALongPathNamesTheWholeFileLineAndField) {
    const std::string out = dir() + "/" + std::string(120, 'd') + "/results-of-the-long-sweep";
    fill(out);
    std::string text = slurp(table_path(out));
    const std::size_t checksum = text.find(",ok,,", text.find("m-1,0,")) + 5;
    text[checksum] = text[checksum] == '0' ? '1' : '0';
    write_file(table_path(out), text);
    EXPECT_EQ(refusal(Shard{}, out), table_path(out) + ":2: field 'checksum': does not match the row and its report "
                                                       "(changed since the sweep wrote them)");
    fs::remove(report_path(out, grid_.point(2)));
    fs::create_symlink("/dev/zero", report_path(out, grid_.point(2)));
    write_file(table_path(out), slurp(table_path(dir())));
    EXPECT_EQ(refusal(Shard{}, out),
              table_path(out) + ":4: the point's report " + report_path(out, grid_.point(2)) + " is not a regular file");
}

TEST_F(SweepDir, AReportOrTableThatIsNoRegularFileIsRefusedUnread) {
    const std::string report = report_path(dir(), grid_.point(2));
    fs::remove(report);
    fs::create_symlink("/dev/zero", report);  // read to the end, it would never end
    EXPECT_EQ(refusal(), table_path(dir()) + ":4: the point's report " + report + " is not a regular file");
    const std::string table = csv();
    fs::remove(table_path(dir()));
    ASSERT_EQ(mkfifo(table_path(dir()).c_str(), 0600), 0);
    EXPECT_EQ(refusal(), table_path(dir()) + ": expected a regular file (the sweep's table)");
}

TEST_F(SweepDir, AHeaderOfAnotherGridIsRefused) {
    edit("checksum,format_version,m", "checksum,format_version,objects");
    EXPECT_EQ(refusal(), table_path(dir()) + ":1: expected the column 'm' of this sweep's grid, got 'objects'");
}

TEST_F(SweepDir, RowsAreAppendedOneLineEachAndPutInPointOrderAtTheEnd) {
    SweepTable table(grid_);
    table.add(2, report_row(grid_, grid_.point(2), kReport, 0.5));
    {
        TableFile file(table_path(dir()), table, true);
        EXPECT_EQ(csv(), table.csv());
        table.add(0, report_row(grid_, grid_.point(0), kReport, 0.5));
        file.append(table, 0);
        EXPECT_EQ(csv(), table.header_line() + table.line(2) + table.line(0)) << "appended, not rewritten";
        file.finish(table);
    }
    EXPECT_EQ(csv(), table.csv()) << "in point order once the sweep ends";
    {
        TableFile file(table_path(dir()), table, false);
        PointRow row = failed_row(grid_, grid_.point(1), PointStatus::kFault, "DMA fault", 0.1);
        row.values["a_new_column"] = "x";
        row.values[kChecksumColumn] = row_checksum(row.values, nullptr);
        table.add(1, row);
        file.append(table, 1);
    }
    EXPECT_EQ(csv(), table.csv()) << "a new column: the file is written again with it";
}

// A sweep of several jobs killed midway leaves its rows in the order they
// finished: resumed, the file is put back in point order before a row is
// appended, whatever the rows still to run.
TEST_F(SweepDir, RowsOutOfPointOrderFromAKilledSweepAreRewrittenInOrderOnResume) {
    SweepTable written(grid_);
    written.add(0, report_row(grid_, grid_.point(0), kReport, 0.5));
    written.add(2, report_row(grid_, grid_.point(2), kReport, 0.5));
    write_file(table_path(dir()), written.header_line() + written.line(2) + written.line(0));
    SweepTable table(grid_);
    const TableRead read = read_table(dir(), grid_, Shard{}, table, false);
    EXPECT_TRUE(read.rewrite) << "rows 2, 0";
    EXPECT_EQ(table.size(), 2u);
    {
        TableFile file(table_path(dir()), table, read.rewrite);
        EXPECT_EQ(csv(), written.csv()) << "in point order before anything is appended";
    }
    write_file(table_path(dir()), written.csv());
    SweepTable again(grid_);
    EXPECT_FALSE(read_table(dir(), grid_, Shard{}, again, false).rewrite) << "rows 0, 2: kept as they are";
}

TEST(SweepCsv, RecordsMayHoldLineEndsInQuotesAndALastRecordMayBeCutShort) {
    std::istringstream in("a,\"b\nc\",d\ne,f");
    CsvRecords records(in, "t.csv");
    std::vector<std::string> fields;
    ASSERT_TRUE(records.next(fields));
    EXPECT_EQ(fields, (std::vector<std::string>{"a", "b\nc", "d"}));
    EXPECT_TRUE(records.complete());
    ASSERT_TRUE(records.next(fields));
    EXPECT_EQ(records.line(), 3u);
    EXPECT_FALSE(records.complete());
    EXPECT_FALSE(records.next(fields));
    std::istringstream long_row(std::string(100, 'x') + "\n");
    CsvRecords limited(long_row, "t.csv", 50);
    EXPECT_THROW(limited.next(fields), InputError);
    std::istringstream unclosed("a,\"b\n");
    CsvRecords open_quote(unclosed, "t.csv");
    EXPECT_THROW(open_quote.next(fields), InputError);
}

class ManifestFile : public ::testing::Test {
protected:
    Manifest manifest() const {
        Manifest m;
        m.axes = {{"m", {"1", "2"}, "board.m", "m"}};
        m.run_options = {"--frames=2"};
        m.inputs = {{"--config", "c.json", "/x/c.json", std::string(64, 'a'), 10, nullptr}};
        m.cdvp_version = "0.1.0";
        return m;
    }
    std::string path() const { return temp_.file("sweep.json"); }
    std::string refusal(const std::string& text) const {
        write_file(path(), text);
        try {
            read_manifest(path());
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    }
    test::TempDir temp_;
};

TEST_F(ManifestFile, RoundTripsAndTellsWhatMakesAnotherSweep) {
    write_file(path(), manifest().to_json().dump(2));
    const std::optional<Manifest> read = read_manifest(path());
    ASSERT_TRUE(read);
    EXPECT_FALSE(difference(*read, manifest()));
    Manifest other = manifest();
    other.inputs[0].sha256 = std::string(64, 'b');
    ASSERT_TRUE(difference(*read, other));
    EXPECT_EQ(difference(*read, other)->what.find("--config c.json changed since the sweep began"), 0u);
    EXPECT_TRUE(difference(*read, other)->input_changed);
    other = manifest();
    other.axes[0].values = {"1", "3"};
    EXPECT_EQ(difference(*read, other)->what, "other values of m");
    other = manifest();
    other.run_options = {"--frames=3"};
    EXPECT_EQ(difference(*read, other)->what, "other options given to every point");
    EXPECT_FALSE(read_manifest(temp_.file("none.json")));
}

TEST_F(ManifestFile, ADamagedManifestIsRefusedNamingTheFileAndWhere) {
    EXPECT_EQ(refusal("{\n  \"format\": x\n}"), path() + ":2:13: not JSON; expected the manifest cdvp sweep writes");
    EXPECT_EQ(refusal(std::string(20000, '[') + std::string(20000, ']')),
              path() + ":1:65: nesting deeper than 64 levels; a sweep manifest nests objects and arrays at most 64 deep");
    EXPECT_EQ(refusal(manifest().to_json().dump() + std::string(1, '\0') + "junk"),
              path() + ":1:" + std::to_string(manifest().to_json().dump().size() + 1) +
                  ": a NUL byte; expected the manifest cdvp sweep writes");
    nlohmann::json text = manifest().to_json();
    text.erase("axes");
    EXPECT_EQ(refusal(text.dump()), path() + ": field 'axes': is missing; expected the manifest cdvp sweep writes");
    text = manifest().to_json();
    text["axes"][0]["values"] = {1, 2};
    EXPECT_EQ(refusal(text.dump()),
              path() + ": field 'axes[0].values': expected a list of strings; expected the manifest cdvp sweep writes");
    text = manifest().to_json();
    text["points"] = 7;
    EXPECT_NE(refusal(text.dump()).find("field 'points': does not match the axes"), std::string::npos);
    text = manifest().to_json();
    text["format"] = "cdvp sweep 1";
    EXPECT_NE(refusal(text.dump()).find("a sweep of another cdvp version"), std::string::npos);
    text = manifest().to_json();
    EXPECT_EQ(text["format_version"], kSweepFormatVersion);
    text["format_version"] = 2;
    EXPECT_EQ(refusal(text.dump()), path() + ": field 'format_version': 2 is not " +
                                        std::to_string(kSweepFormatVersion) +
                                        " (a sweep of another cdvp version: give a new --out); expected the manifest "
                                        "cdvp sweep writes");
    text.erase("format_version");
    EXPECT_EQ(refusal(text.dump()),
              path() + ": field 'format_version': is missing; expected the manifest cdvp sweep writes");
}

}  // namespace
}  // namespace cdvp
