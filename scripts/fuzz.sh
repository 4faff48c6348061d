#!/usr/bin/env bash
# Builds the libFuzzer targets in fuzz/ with clang into build-fuzz/ and runs each for SECONDS (default 60)
# on one core, one after the other. Corpora grow in build-fuzz/corpus/TARGET/ (seeded from effects/,
# tests/data/, fuzz/seeds/ and scenes/); a crash leaves build-fuzz/artifacts/TARGET/crash-* and fails the script.
# Every crash found is fixed and added to tests/data/malformed/ with its golden diagnostics.
#   scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(fuzz_effect_parser fuzz_effect_compiler fuzz_compile_workers fuzz_sas_script fuzz_dds_file)
  [ -f runtime/assets/include/runtime/SceneFile.h ] && targets+=(fuzz_scene_file)
fi

scripts/install-deps.sh >/dev/null
# libFuzzer ships with clang's runtime libraries (Debian: clang + libclang-rt-14-dev).
if ! command -v clang++ >/dev/null || ! dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null | grep -q "ok installed"; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO apt-get install -y --no-install-recommends clang libclang-rt-14-dev >/dev/null
fi
# -O1 and line tables only: the flags fuzzing infrastructure (OSS-Fuzz) builds libFuzzer targets with.
opt="-O1 -gline-tables-only -DNDEBUG"
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWFX_FUZZ=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$opt" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$opt" \
  -DSHADOWFX_BUILD_TESTS=OFF -DSHADOWFX_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]}" shadowfx-compile-worker

root="$(pwd)"
seed() {  # seed TARGET: fills an empty corpus from the checked-in inputs
  local dir="build-fuzz/corpus/$1"
  mkdir -p "$dir"
  [ -n "$(ls -A "$dir")" ] && return 0
  case "$1" in
    fuzz_effect_parser | fuzz_effect_compiler | fuzz_compile_workers)
      # tests/data/glslang_crashes/ crash glslang: a finding for fuzz_effect_compiler on its first input.
      local skip='^$'
      [ "$1" = fuzz_effect_compiler ] && skip='^tests/data/glslang_crashes/'
      find effects tests/data fuzz/seeds -name '*.fx' -o -name '*.fxh' | grep -v "$skip" | while read -r f; do
        [ "$(stat -c %s "$f")" -le 65536 ] && cp "$f" "$dir/$(echo "$f" | tr / _)"
      done ;;
    fuzz_sas_script)  # the value of every Script annotation
      grep -rhoE 'Script *= *"[^"]*"' effects tests/data | sed -E 's/^Script *= *"(.*)"$/\1/' | sort -u |
        while read -r s; do printf '%s' "$s" > "$dir/$(printf '%s' "$s" | md5sum | cut -c1-16)"; done ;;
    fuzz_dds_file)  # one small file of each family: masks, float components, blocks, a DX10 header
      cp fuzz/seeds/*.dds "$dir/" ;;
    fuzz_scene_file)
      find scenes tests/data -name '*.json' 2>/dev/null | while read -r f; do cp "$f" "$dir/$(echo "$f" | tr / _)"; done
      [ -n "$(ls -A "$dir")" ] || echo '{}' > "$dir/empty.json" ;;
  esac
}

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}" LP_NUM_THREADS=1
status=0
for target in "${targets[@]}"; do
  seed "$target"
  mkdir -p "build-fuzz/artifacts/$target"
  # Run in an empty folder: the scene loader resolves mesh paths there, not in the repository.
  work="$(mktemp -d)"
  echo "== $target: ${seconds}s"
  if ! (cd "$work" && "$root/build-fuzz/fuzz/$target" -max_total_time="$seconds" -max_len=65536 -timeout=20 \
          -rss_limit_mb=3072 -print_final_stats=1 -artifact_prefix="$root/build-fuzz/artifacts/$target/" \
          "$root/build-fuzz/corpus/$target" 2>&1 | tee "$root/build-fuzz/$target.log" | grep -E '^(#[0-9]+.*DONE|stat::|==[0-9]+==ERROR|SUMMARY)' ); then
    :
  fi
  if ls "build-fuzz/artifacts/$target"/crash-* "build-fuzz/artifacts/$target"/timeout-* "build-fuzz/artifacts/$target"/oom-* >/dev/null 2>&1; then
    echo "$target: findings in build-fuzz/artifacts/$target/"; status=1
  fi
  echo "corpus: $(ls "build-fuzz/corpus/$target" | wc -l) inputs"
  rm -rf "$work"
done
exit $status
