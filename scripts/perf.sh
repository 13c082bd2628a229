#!/usr/bin/env bash
# Performance (issue #8): builds snow_bench (Release) if needed, runs it with
# repetitions to JSON, prints the median tables that docs/performance.md
# quotes and redraws docs/img/perf_scaling.png (flakes vs ms per tick, 1 and
# 2 threads) with gnuplot. The whole run takes several minutes on 2 cores.
# Usage: scripts/perf.sh [extra snow_bench options]
# Environment: BUILD_DIR (default build, must be a Release tree), JOBS (default:
#   cores), REPS (repetitions, default 3), FILTER (benchmark regex, default all),
#   OUT (folder for perf.json and tables.md, default $BUILD_DIR/perf-out),
#   PERF_JSON (an existing snow_bench JSON: skip building and running, only
#   redo the tables and the plot from it, e.g. merged from separate runs).
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-$(nproc)}
REPS=${REPS:-3}
FILTER=${FILTER:-.}
OUT=${OUT:-$BUILD_DIR/perf-out}

if ! command -v gnuplot >/dev/null 2>&1; then
    echo "[perf] error: gnuplot is missing; run scripts/deps.sh (gnuplot-nox)" >&2
    exit 1
fi
mkdir -p "$OUT" docs/img
if [ -n "${PERF_JSON:-}" ]; then
    [ "$PERF_JSON" -ef "$OUT/perf.json" ] || cp "$PERF_JSON" "$OUT/perf.json"
else
    if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
        echo "[perf] configuring $BUILD_DIR (Release)"
        cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
    fi
    build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$BUILD_DIR/CMakeCache.txt")
    if [ "$build_type" != Release ]; then
        echo "[perf] error: $BUILD_DIR is a '$build_type' build; timings need Release" \
             "(set BUILD_DIR to another folder)" >&2
        exit 1
    fi
    echo "[perf] building snow_bench in $BUILD_DIR"
    cmake --build "$BUILD_DIR" -j "$JOBS" --target snow_bench

    echo "[perf] running (load before: $(cut -d' ' -f1-3 /proc/loadavg))"
    "$BUILD_DIR/bench/snow_bench" --benchmark_filter="$FILTER" \
        --benchmark_repetitions="$REPS" --benchmark_report_aggregates_only=true \
        --benchmark_out="$OUT/perf.json" --benchmark_out_format=json "$@"
    echo "[perf] load after: $(cut -d' ' -f1-3 /proc/loadavg)"
fi

# Medians out of the JSON: the tables (markdown) and the plot data.
python3 - "$OUT" <<'EOF'
import json, re, sys
out = sys.argv[1]
runs = json.load(open(f"{out}/perf.json"))["benchmarks"]
med = {b["run_name"]: b for b in runs if b.get("aggregate_name") == "median"}
MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}

def ms(b):
    return b["real_time"] * MS[b["time_unit"]]

def arg(name, key):
    m = re.search(rf"{key}:(\d+)", name)
    return int(m.group(1)) if m else None

lines = []
def table(title, head, rows):
    if rows:
        lines.extend([f"**{title}**", "", "| " + " | ".join(head) + " |",
                      "|" + "---|" * len(head)] + ["| " + " | ".join(r) + " |" for r in rows] + [""])

def per_flake(family):
    rows, data = [], []
    sizes = sorted({arg(n, "flakes") for n in med if n.startswith(family + "/")})
    for n in sizes:
        cell = {}
        for t in (1, 2):
            b = med.get(f"{family}/flakes:{n}/threads:{t}/real_time")
            if b:
                cell[t] = (ms(b), b["ns_per_flake"], b["flakes"])
        if cell:
            fl = next(iter(cell.values()))[2]
            rows.append([f"{n:,}", f"{fl:,.0f}"] + [
                f"{cell[t][0]:.3f} ms · {cell[t][1]:.2f} ns" if t in cell else "–" for t in (1, 2)])
            data.append((fl, cell.get(1, (float("nan"),))[0], cell.get(2, (float("nan"),))[0]))
    return rows, data

head = ["flakes (prefilled)", "alive (mean)", "1 thread: per tick · per flake",
        "2 threads: per tick · per flake"]
rows, scaling = per_flake("BM_SimTick")
table("BM_SimTick (snowfall: flakes at every height, some land each tick)", head, rows)
rows, _ = per_flake("BM_SimTickAloft")
table("BM_SimTickAloft (flakes in the upper half: nothing lands)", head, rows)
for fam in ("BM_Integrate", "BM_Collide", "BM_Deposit"):
    rows, _ = per_flake(fam)
    table(f"{fam} (the system alone, snowfall world)", head, rows)

rows = [[n.split("/", 1)[1], f"{ms(b) * 1e3:.1f} µs", f"{b.get('smoothing_iterations', 0):.0f}"]
        for n, b in med.items() if n.startswith("BM_Redistribute/")]
table("BM_Redistribute (a landing patch at the centre; one tick)",
      ["surface / patch", "time", "smoothing steps"], rows)
rows = [[n.split("/", 1)[1], f"{ms(b) * 1e3:.1f} µs"]
        for n, b in med.items() if n.startswith(("BM_RedistributeScattered/", "BM_Spill/"))]
table("BM_RedistributeScattered and BM_Spill", ["case", "time"], rows)
rows = [[n.split("/", 1)[1], f"{ms(b):.2f} ms"]
        for n, b in med.items() if n.startswith("BM_OcclusionRefresh/")]
table("BM_OcclusionRefresh (one full rebuild of the sky map)", ["case", "time"], rows)
rows = [[n.split("/", 1)[0], n.split("/", 1)[1], f"{ms(b):.3f} ms",
         f"{b['flake_pass_ms']:.2f} ms" if "flake_pass_ms" in b else
         f"{b['ns_per_flake']:.2f} ns/flake"]
        for n, b in med.items() if n.startswith(("BM_FlakeSelection/", "BM_RenderUpload/"))]
table("Render upload (OSMesa llvmpipe, 320×240)", ["benchmark", "case", "time", "detail"], rows)
rows = [[n.split("/", 1)[1], f"{b['bytes_per_second'] / 1e9:.1f} GB/s"]
        for n, b in med.items() if n.startswith("BM_MemoryCopy/")]
table("BM_MemoryCopy (read + written bytes, all threads)", ["case", "bandwidth"], rows)

open(f"{out}/tables.md", "w").write("\n".join(lines))
with open(f"{out}/scaling.dat", "w") as f:
    f.write("# alive_flakes ms_1_thread ms_2_threads\n")
    for fl, a, b in scaling:
        f.write(f"{fl:.0f} {a:.6f} {b:.6f}\n")
print("\n".join(lines))
EOF

gnuplot <<EOF
set terminal pngcairo size 800,520 font ",11"
set output "docs/img/perf_scaling.png"
set title "snow: full simulation tick (BM_SimTick, snowfall yard, 512² ground)" noenhanced
set xlabel "flakes alive"
set ylabel "ms per tick (median of ${REPS})"
set logscale xy
set grid
set key top left
set format x "%.0s%c"
plot "$OUT/scaling.dat" using 1:2 with linespoints lw 2 pt 7 title "1 thread", \
     "$OUT/scaling.dat" using 1:3 with linespoints lw 2 pt 5 title "2 threads", \
     "$OUT/scaling.dat" using 1:(\$1*3.5e-6) with lines dt 2 lc rgb "gray" title "goal 1 thread (3.5 ns/flake)", \
     "$OUT/scaling.dat" using 1:(\$1*2.0e-6) with lines dt 3 lc rgb "black" title "goal 2 threads (2.0 ns/flake)"
EOF
echo "[perf] wrote $OUT/perf.json, $OUT/tables.md and docs/img/perf_scaling.png"
