// `bench --shard K/N` (report/BenchShard.h): the parse of K/N, and the split itself: every run index in
// exactly one shard, shares that differ by at most one run, and neighbouring runs in different shards.
#include <report/BenchShard.h>

#include <gtest/gtest.h>

#include <vector>

namespace shadowfx::test::test_bench_shard {
namespace {

TEST(BenchShard, ParsesKOfN) {
    std::string error;
    const std::optional<report::BenchShard> shard = report::parseBenchShard("2/8", error);
    ASSERT_TRUE(shard) << error;
    EXPECT_EQ(shard->index, 2);
    EXPECT_EQ(shard->count, 8);
    EXPECT_EQ(shard->label(), "2/8");
    ASSERT_TRUE(report::parseBenchShard("1/1", error)) << error;
}

TEST(BenchShard, RefusesWhatIsNotKOfN) {
    for (const char* text : {"", "3", "0/3", "4/3", "1/0", "-1/3", "1/3x", "a/b", "1//3", "/3", "2/"}) {
        std::string error;
        EXPECT_FALSE(report::parseBenchShard(text, error)) << text;
        EXPECT_NE(error.find(text), std::string::npos) << "the message names the value: " << error;
    }
}

TEST(BenchShard, EveryRunIsInExactlyOneShardAndSharesDifferByOneAtMost) {
    for (int count = 1; count <= 7; ++count) {
        for (size_t total : {size_t{0}, size_t{1}, size_t{5}, size_t{12}, size_t{13}}) {
            std::vector<int> owners(total, 0);
            size_t smallest = total, largest = 0;
            for (int k = 1; k <= count; ++k) {
                const report::BenchShard shard{k, count};
                size_t taken = 0;
                for (size_t run = 0; run < total; ++run) {
                    if (!shard.takes(run)) continue;
                    ++owners[run];
                    ++taken;
                }
                EXPECT_EQ(taken, shard.runsOf(total)) << shard.label() << " of " << total;
                smallest = std::min(smallest, taken);
                largest = std::max(largest, taken);
            }
            for (size_t run = 0; run < total; ++run) EXPECT_EQ(owners[run], 1) << "run " << run;
            EXPECT_LE(largest - smallest, 1u) << count << " shards of " << total;
        }
    }
}

TEST(BenchShard, NeighbouringRunsGoToDifferentShards) {
    // Dealt round-robin: a stretch of N costly neighbours (one heavy scene, one big map) lands on N shards.
    const report::BenchShard first{1, 3};
    EXPECT_TRUE(first.takes(0));
    EXPECT_FALSE(first.takes(1));
    EXPECT_FALSE(first.takes(2));
    EXPECT_TRUE(first.takes(3));
    EXPECT_TRUE((report::BenchShard{3, 3}.takes(2)));
}

}  // namespace
}  // namespace shadowfx::test::test_bench_shard
