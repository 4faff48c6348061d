// NameLookups: see NameLookups.h.
#include <private/runtime/NameLookups.h>

#include <atomic>

namespace runtime {

namespace {
std::atomic<uint64_t> gNameLookups{0};
}  // namespace

void countNameLookup() {
    gNameLookups.fetch_add(1, std::memory_order_relaxed);
}

uint64_t nameLookups() {
    return gNameLookups.load(std::memory_order_relaxed);
}

}  // namespace runtime
