// Whether this build has OpenSceneGraph's peer (benchmarks/peers/), for the tests that run it. The sanitized
// build never builds it (OpenSceneGraph is not instrumented): there a peer test skips and says why. Anywhere
// else a missing peer means OpenSceneGraph, which scripts/install-deps.sh installs, was not found: the test
// fails, so that a plain build cannot pass without it. tests/CMakeLists.txt defines which case holds.
#pragma once

#include <gtest/gtest.h>

#if defined(SHADOWFX_OSG_PEER_SANITIZED)
#define SHADOWFX_REQUIRE_OSG_PEER() \
    GTEST_SKIP() << "sanitized build: shadowfx-osg-peer is not built (OpenSceneGraph is not instrumented)"
#elif !defined(SHADOWFX_OSG_PEER_BUILT)
#define SHADOWFX_REQUIRE_OSG_PEER()                                                    \
    FAIL() << "shadowfx-osg-peer is not built: CMake did not find OpenSceneGraph 3.6 " \
              "(libopenscenegraph-dev, which scripts/install-deps.sh installs)"
#else
#define SHADOWFX_REQUIRE_OSG_PEER() static_cast<void>(0)
#endif
