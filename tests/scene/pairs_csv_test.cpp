#include "sw/scene/pairs_csv.h"

#include <gtest/gtest.h>

#include <sstream>

#include "tests/scene/temp_dir.h"

namespace cdvp {
namespace {

using Rows = std::vector<std::pair<uint64_t, IdPair>>;

TEST(PairsCsv, ToIdPairsMapsOrdersAndSorts) {
    Frame frame{3, {50, 7, 900, 8}, std::vector<Box>(4)};
    PairList pairs{{0, 1}, {2, 3}, {1, 3}, {0, 2}};
    std::vector<IdPair> expected{{7, 8}, {7, 50}, {8, 900}, {50, 900}};
    EXPECT_EQ(expected, to_id_pairs(frame, pairs));
    EXPECT_TRUE(to_id_pairs(frame, {}).empty());
    EXPECT_THROW(to_id_pairs(frame, {{0, 4}}), std::out_of_range);
}

TEST(PairsCsv, IdPairOrdering) {
    EXPECT_LT((IdPair{1, 9}), (IdPair{2, 3}));
    EXPECT_LT((IdPair{2, 3}), (IdPair{2, 4}));
    EXPECT_FALSE((IdPair{2, 4}) < (IdPair{2, 4}));
    EXPECT_EQ((IdPair{2, 4}), (IdPair{2, 4}));
}

TEST(PairsCsv, WriteThenReadBack) {
    test::TempDir dir;
    std::string path = dir.file("pairs.csv");
    {
        std::ofstream out(path);
        write_pairs_header(out);
        write_frame_pairs(out, 0, {{1, 2}, {1, 18446744073709551615ULL}});
        write_frame_pairs(out, 1, {});
        write_frame_pairs(out, 4, {{0, 3}});
    }
    EXPECT_EQ("frame,a,b\n0,1,2\n0,1,18446744073709551615\n4,0,3\n", test::slurp(path));
    Rows expected{{0, {1, 2}}, {0, {1, 18446744073709551615ULL}}, {4, {0, 3}}};
    EXPECT_EQ(expected, read_pairs_csv(path));
}

TEST(PairsCsv, ReadRejectsBadContent) {
    test::TempDir dir;
    std::string path = dir.file("p.csv");
    struct Case {
        const char* text;
        const char* line;
    };
    for (Case c : {Case{"frame,x,y\n", ":1: "}, Case{"frame,a,b\n0,1\n", ":2: "},
                   Case{"frame,a,b\r\n0,1,2\r\n0,3,2\n", ":3: "},
                   Case{"frame,a,b\n0,1,2\n0,x,3\n", ":3: "},
                   Case{"frame,a,b\n0,1,1\n", ":2: "}}) {
        test::spit(path, c.text);
        try {
            read_pairs_csv(path);
            ADD_FAILURE() << "no exception for " << c.text;
        } catch (const InputError& e) {
            EXPECT_EQ(0u, std::string(e.what()).rfind(path + c.line, 0)) << e.what();
        }
    }
    EXPECT_THROW(read_pairs_csv(dir.file("missing.csv")), InputError);
}

}  // namespace
}  // namespace cdvp
