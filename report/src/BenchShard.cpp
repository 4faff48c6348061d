// BenchShard: see BenchShard.h.
#include <report/BenchShard.h>

#include <charconv>

namespace report {

size_t BenchShard::runsOf(size_t totalRuns) const {
    const size_t n = static_cast<size_t>(count);
    const size_t k = static_cast<size_t>(index - 1);
    return totalRuns / n + (k < totalRuns % n ? 1 : 0);
}

std::optional<BenchShard> parseBenchShard(const std::string& text, std::string& error) {
    const size_t slash = text.find('/');
    BenchShard shard;
    const auto number = [&](size_t from, size_t to, int& out) {
        const char* first = text.data() + from;
        const char* last = text.data() + to;
        const auto [end, code] = std::from_chars(first, last, out);
        return first != last && end == last && code == std::errc();
    };
    if (slash == std::string::npos || !number(0, slash, shard.index) ||
        !number(slash + 1, text.size(), shard.count)) {
        error = "'" + text + "' is not K/N (shard K of N, e.g. 2/8)";
        return std::nullopt;
    }
    if (shard.count < 1 || shard.index < 1 || shard.index > shard.count) {
        error = "'" + text + "': K must be between 1 and N, N at least 1";
        return std::nullopt;
    }
    return shard;
}

}  // namespace report
