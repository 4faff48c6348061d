// NameLookups: how often the runtime resolved a name (a parameter, light, technique or semantic found by
// its text) or parsed a literal from text. Everything the compiled effect and the scene name is resolved
// once, when the effect or the scene is created or changes; a frame that changed neither should resolve
// nothing, and tests (test_frame_overhead.cpp) hold the frame to that by reading this count around it.
//
// Always counted, not only in debug builds: the tests run the optimized build CI ships, and one relaxed
// increment is nothing beside a search through a table of names.
#pragma once

#include <cstdint>

namespace runtime {

// Called by every function that searches by name or parses text (Scene::findLight,
// EffectResources::findParameter, ...).
void countNameLookup();
// The lookups counted since the process started, on every thread.
uint64_t nameLookups();

}  // namespace runtime
