#!/usr/bin/env bash
# Fuzzes the scene loader (tests/fuzz/gltf_fuzzer.cpp) with libFuzzer, ASan and UBSan for MINUTES
# minutes on one core. Seeds: every file of tests/data/gltf, scenes/ and tests/data/fuzz (earlier
# findings). New findings are minimised into out/fuzz/findings/; copy each into tests/data/fuzz/
# once it is fixed, where the test suite checks that it fails cleanly.
# Usage: scripts/fuzz.sh [MINUTES] [JOBS]   (defaults: 30 minutes, 1 job)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MINUTES="${1:-30}"
JOBS="${2:-1}"
[[ "$MINUTES" =~ ^[1-9][0-9]*$ ]] || { echo "usage: scripts/fuzz.sh [MINUTES >= 1] [JOBS]" >&2; exit 2; }
BUILD="$ROOT/build-fuzz"
OUT="$ROOT/out/fuzz"

missing=()
for p in clang-14 libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# The rest of the dependencies are those of the normal build.
BUILD_DIR="$ROOT/build" source "$ROOT/scripts/setup.sh" > /dev/null

mkdir -p "$BUILD"
cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DRELT_FUZZ=ON -DRELT_BUILD_TESTS=OFF > "$BUILD/configure.log" 2>&1 || { cat "$BUILD/configure.log"; exit 1; }
cmake --build "$BUILD" --target relt_fuzz_gltf

mkdir -p "$OUT/corpus" "$OUT/crashes" "$OUT/findings" "$OUT/seeds"
find "$ROOT/tests/data/gltf" "$ROOT/scenes" "$ROOT/tests/data/fuzz" -type f \( -name '*.gltf' -o -name '*.glb' \) \
  -exec cp {} "$OUT/seeds/" \; 2>/dev/null || true
# The harness sees one file: seeds whose buffers live in .bin files next to them get the buffers
# embedded as data URIs, so that whole scenes load and the render path is fuzzed too.
/usr/bin/python3 - "$OUT/seeds" "$ROOT/scenes" "$ROOT/tests/data/gltf" <<'PY'
import base64, json, os, sys
out = sys.argv[1]
for top in sys.argv[2:]:
    for folder, _, names in os.walk(top):
        for name in names:
            if not name.endswith(".gltf"):
                continue
            try:
                doc = json.load(open(os.path.join(folder, name)))
                for b in doc.get("buffers", []):
                    uri = b.get("uri", "")
                    if uri and not uri.startswith("data:"):
                        data = open(os.path.join(folder, uri), "rb").read()
                        b["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
                if len(json.dumps(doc)) < 1 << 20:
                    json.dump(doc, open(os.path.join(out, "embedded-" + name), "w"))
            except (OSError, ValueError, AttributeError, TypeError):
                pass  # invalid files are seeds as they are
PY

# Leaks are reported by ASan at exit; the loader's error paths must not leak either.
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd "$OUT"
set +e
"$BUILD/relt_fuzz_gltf" "$OUT/corpus" "$OUT/seeds" -dict="$ROOT/tests/fuzz/gltf.dict" \
  -max_total_time=$((MINUTES * 60)) -timeout=20 -rss_limit_mb=4096 -malloc_limit_mb=2048 \
  -artifact_prefix="$OUT/crashes/" -print_final_stats=1 $( ((JOBS > 1)) && echo "-jobs=$JOBS -workers=$JOBS") \
  > "$OUT/fuzz.log" 2>&1
grep -hE "^#[0-9]+ +DONE|ERROR|SUMMARY|stat::number_of_executed_units" "$OUT"/fuzz*.log || true
set -e

# Minimise every finding (smallest input that still fails the same way).
count=0
for f in "$OUT"/crashes/*; do
  [ -f "$f" ] || continue
  count=$((count + 1))
  "$BUILD/relt_fuzz_gltf" -minimize_crash=1 -runs=20000 -exact_artifact_path="$OUT/findings/$(basename "$f")" "$f" \
    > "$OUT/findings/$(basename "$f").log" 2>&1 || true
done
echo "fuzz: $MINUTES min, $count finding(s); corpus $(ls "$OUT/corpus" | wc -l) files; findings in $OUT/findings"
