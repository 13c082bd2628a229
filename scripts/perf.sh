#!/usr/bin/env bash
# Performance (issues #8, #16): builds snow_bench (Release) if needed, runs it
# with repetitions to JSON and, when SNOW_YARDSTICK names a built yardstick
# binary (a speed-of-light reference run beside snow_bench; not part of the
# project), runs that too at 100k and 1M flakes, before and after snow_bench
# (the faster of the two runs counts). Then writes the median
# tables, the ratios of BM_SimTick to BM_SpeedOfLight (and to the yardstick),
# the two-thread speed-ups and the load average into the generated section of
# docs/performance.md (between its "perf.sh" markers), and redraws
# docs/img/perf_scaling.png (flakes vs ms per tick, 1 and 2 threads) with
# gnuplot. The whole run takes several minutes on 2 cores.
# Usage: scripts/perf.sh [extra snow_bench options]
# Environment: BUILD_DIR (default build, must be a Release tree), JOBS (default:
#   cores), REPS (repetitions, default 3), FILTER (benchmark regex, default all),
#   OUT (folder for perf.json, yardstick_*.txt, run.txt and tables.md, default
#   $BUILD_DIR/perf-out), PERF_JSON (an existing snow_bench JSON: skip building
#   and running, only redo the tables and the plot from it and from what OUT
#   already holds), SNOW_YARDSTICK (path of the yardstick binary; its output
#   must end in "ref_ns_per_flake_1t X" and "ref_ns_per_flake_2t X" lines),
#   DOC (the page to write, default docs/performance.md; DOC=none: only OUT).
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-$(nproc)}
REPS=${REPS:-3}
FILTER=${FILTER:-.}
OUT=${OUT:-$BUILD_DIR/perf-out}
DOC=${DOC:-docs/performance.md}
YARDSTICK_SIZES="100000 1000000"

if ! command -v gnuplot >/dev/null 2>&1; then
    echo "[perf] error: gnuplot is missing; run scripts/deps.sh (gnuplot-nox)" >&2
    exit 1
fi
if [ -n "${SNOW_YARDSTICK:-}" ] && [ ! -x "$SNOW_YARDSTICK" ]; then
    echo "[perf] error: SNOW_YARDSTICK=$SNOW_YARDSTICK is not an executable file" >&2
    exit 1
fi
if [ "$DOC" != none ] && ! grep -q '^<!-- perf.sh begin' "$DOC"; then
    echo "[perf] error: $DOC has no '<!-- perf.sh begin' marker line to write after" >&2
    exit 1
fi
mkdir -p "$OUT" docs/img
loadavg() { cut -d' ' -f1-3 /proc/loadavg; }
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

    rm -f "$OUT"/yardstick_*.txt
    # The yardstick runs before and after snow_bench, and the faster of the
    # two counts: a run slowed by the VM's neighbours would flatter the ratio.
    run_yardstick() {
        echo "load_yardstick_$1 $(loadavg)" >>"$OUT/run.txt"
        for n in $YARDSTICK_SIZES; do
            echo "[perf] running the yardstick at $n flakes ($1 snow_bench)"
            "$SNOW_YARDSTICK" --flakes "$n" | tee "$OUT/yardstick_${n}_$1.txt"
        done
    }
    {
        echo "date $(date -u '+%Y-%m-%d %H:%M UTC')"
        echo "commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
        echo "cpu $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1), $(nproc) cores"
    } >"$OUT/run.txt"
    if [ -n "${SNOW_YARDSTICK:-}" ]; then
        run_yardstick before
    fi
    echo "[perf] running snow_bench (load before: $(loadavg))"
    echo "load_bench_before $(loadavg)" >>"$OUT/run.txt"
    # Repetitions of all benchmarks in random order: the VM's slow minutes
    # then fall on one thread and two alike, not on whichever ran then.
    "$BUILD_DIR/bench/snow_bench" --benchmark_filter="$FILTER" \
        --benchmark_repetitions="$REPS" --benchmark_enable_random_interleaving=true \
        --benchmark_report_aggregates_only=true \
        --benchmark_out="$OUT/perf.json" --benchmark_out_format=json "$@"
    echo "load_bench_after $(loadavg)" >>"$OUT/run.txt"
    echo "[perf] load after: $(loadavg)"
    if [ -n "${SNOW_YARDSTICK:-}" ]; then
        run_yardstick after
    fi
fi

# Medians out of the JSON: the tables (markdown), the plot data and the
# generated section of the page.
python3 - "$OUT" "$REPS" "$DOC" <<'EOF'
import glob, json, os, re, sys
out, reps, doc = sys.argv[1], sys.argv[2], sys.argv[3]
runs = json.load(open(f"{out}/perf.json"))["benchmarks"]
med = {b["run_name"]: b for b in runs if b.get("aggregate_name") == "median"}
MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}

def ms(b):
    return b["real_time"] * MS[b["time_unit"]]

def arg(name, key):
    m = re.search(rf"{key}:(\d+)", name)
    return int(m.group(1)) if m else None

def flake_run(family, flakes, threads):
    return med.get(f"{family}/flakes:{flakes}/threads:{threads}/real_time")

meta = {}
if os.path.exists(f"{out}/run.txt"):
    for line in open(f"{out}/run.txt"):
        key, _, value = line.strip().partition(" ")
        meta[key] = value

# The yardstick's best ns per flake, per size and thread count: the faster
# of its runs (before and after snow_bench), each run's kept for the intro.
yard, yard_runs = {}, {}
def run_order(path):
    return ("_before" not in path, "_after" not in path, path)
for path in sorted(glob.glob(f"{out}/yardstick_*.txt"), key=run_order):
    n = int(re.search(r"yardstick_(\d+)(_[a-z]+)?\.txt$", path).group(1))
    for line in open(path):
        m = re.match(r"ref_ns_per_flake_([12])t\s+([0-9.eE+-]+)", line)
        if m:
            key, v = (n, int(m.group(1))), float(m.group(2))
            yard_runs.setdefault(key, []).append(v)
            yard[key] = min(yard.get(key, v), v)

lines = []
def table(title, head, rows):
    if rows:
        lines.extend([f"**{title}**", "", "| " + " | ".join(head) + " |",
                      "|" + "---|" * len(head)] + ["| " + " | ".join(r) + " |" for r in rows] + [""])

def ns(v):
    return f"{v:.2f}" if v is not None else "–"

def ratio(a, b):
    return f"{a / b:.2f}×" if a is not None and b else "–"

def nspf(b):
    return b["ns_per_flake"] if b else None

# Against the limit (issue #16): per flake, BM_SimTick over the references.
goals = {(1000000, 1): "≤ 1.2× yardstick", (1000000, 2): "≤ 1.35× yardstick",
         (100000, 1): "≤ 1.2× yardstick"}
rows = []
for n in (100000, 1000000):
    for t in (1, 2):
        tick, sol = nspf(flake_run("BM_SimTick", n, t)), nspf(flake_run("BM_SpeedOfLight", n, t))
        aloft, ref = nspf(flake_run("BM_SimTickAloft", n, t)), yard.get((n, t))
        if tick is None and sol is None:
            continue
        rows.append([f"{n:,}", str(t), ns(tick), ns(aloft), ns(sol), ns(ref), ratio(tick, sol),
                     ratio(tick, ref), goals.get((n, t), "–")])
table("BM_SimTick against BM_SpeedOfLight and the yardstick (ns per flake; ratio = BM_SimTick / reference)",
      ["flakes", "threads", "BM_SimTick", "BM_SimTickAloft", "BM_SpeedOfLight", "yardstick",
       "SimTick / SpeedOfLight", "SimTick / yardstick", "goal"], rows)

# Two threads against one: wall time per tick.
rows = []
def speedup_row(label, one, two, goal):
    if one is not None and two is not None:
        rows.append([label, f"{one:.3f}", f"{two:.3f}", f"{one / two:.2f}×", goal])
for family in ("BM_SimTick", "BM_SimTickAloft", "BM_SpeedOfLight"):
    for n in sorted({arg(k, "flakes") for k in med if k.startswith(family + "/")}):
        a, b = flake_run(family, n, 1), flake_run(family, n, 2)
        goal = ("≥ 1.4×" if n == 1000000 else "≥ 1.0×") if family.startswith("BM_SimTick") else "–"
        speedup_row(f"{family} {n:,}", ms(a) if a else None, ms(b) if b else None, goal)
a, b = med.get("BM_VillageTick/threads:1/real_time"), med.get("BM_VillageTick/threads:2/real_time")
speedup_row("BM_VillageTick", ms(a) if a else None, ms(b) if b else None, "≥ 1.0×")
for n in (100000, 1000000):
    if (n, 1) in yard and (n, 2) in yard:
        rows.append([f"yardstick {n:,} (ns per flake)", f"{yard[(n, 1)]:.3f}", f"{yard[(n, 2)]:.3f}",
                     f"{yard[(n, 1)] / yard[(n, 2)]:.2f}×", "–"])
table("Two threads against one (ms per tick; speed-up = 1 thread / 2 threads)",
      ["benchmark", "1 thread", "2 threads", "speed-up", "goal"], rows)

def per_flake(family):
    rows, data = [], []
    sizes = sorted({arg(n, "flakes") for n in med if n.startswith(family + "/")})
    for n in sizes:
        cell = {}
        for t in (1, 2):
            b = flake_run(family, n, t)
            if b:
                cell[t] = (ms(b), b["ns_per_flake"], b.get("cpu_ns_per_flake"), b["flakes"])
        if cell:
            fl = next(iter(cell.values()))[3]
            rows.append([f"{n:,}", f"{fl:,.0f}"] + [
                f"{cell[t][0]:.3f} ms · {cell[t][1]:.2f} ns · {ns(cell[t][2])}" if t in cell
                else "–" for t in (1, 2)])
            data.append((fl, cell.get(1, (float("nan"),))[0], cell.get(2, (float("nan"),))[0]))
    return rows, data

head = ["flakes (prefilled)", "alive (mean)", "1 thread: per tick · per flake · CPU per flake",
        "2 threads: per tick · per flake · CPU per flake"]
rows, scaling = per_flake("BM_SimTick")
table("BM_SimTick (snowfall: flakes at every height, some land each tick)", head, rows)
rows, _ = per_flake("BM_SimTickAloft")
table("BM_SimTickAloft (flakes in the upper half: nothing lands)", head, rows)
rows, limit = per_flake("BM_SpeedOfLight")
table("BM_SpeedOfLight (the bare core loop: integrate, height test, deposit; one pass)", head, rows)
for fam in ("BM_Integrate", "BM_Collide", "BM_Deposit"):
    rows, _ = per_flake(fam)
    table(f"{fam} (the system alone, snowfall world)", head, rows)
rows = [[n.split("/", 1)[1].replace("/real_time", ""), f"{ms(b):.3f} ms",
         f"{b['ns_per_flake']:.2f} ns · {ns(b.get('cpu_ns_per_flake'))}", f"{b['flakes']:,.0f}"]
        for n, b in med.items() if n.startswith("BM_VillageTick/")]
table("BM_VillageTick (assets/scenes/village.gltf, steady snowfall)",
      ["case", "per tick", "per flake · CPU per flake", "alive (mean)"], rows)

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

def load1(key):
    return meta.get(key, "?").split(" ")[0]
intro = [
    f"Run of {meta.get('date', '(date not recorded)')}, commit {meta.get('commit', '?')}, "
    f"{meta.get('cpu', 'CPU not recorded')}; median of {reps} repetitions. Load average "
    f"(1 min) {load1('load_bench_before')} before and {load1('load_bench_after')} after snow_bench"
    + (f", {load1('load_yardstick_before')} before the yardstick's first run and "
       f"{load1('load_yardstick_after')} before its second" if yard
       else "; no yardstick run (SNOW_YARDSTICK unset)") + "."
    + (" The yardstick ran before and after snow_bench; the faster run counts (ns per flake, "
       "before / after: " + ", ".join(f"{n / 1e6:g}M {t}t " + " / ".join(f"{v:.2f}" for v in vs)
                                   for (n, t), vs in sorted(yard_runs.items())) + ")."
       if yard else ""),
    "Per flake: wall time per tick / flakes alive in it (`ns_per_flake`) and the CPU time of all "
    "threads over the same ticks (`cpu_ns_per_flake`); on a loaded machine the first waits for "
    "other processes and the second does not.", ""]
section = intro + lines
open(f"{out}/tables.md", "w").write("\n".join(section))
with open(f"{out}/scaling.dat", "w") as f:
    f.write("# alive_flakes ms_1_thread ms_2_threads\n")
    for fl, a, b in scaling:
        f.write(f"{fl:.0f} {a:.6f} {b:.6f}\n")
with open(f"{out}/limit.dat", "w") as f:
    f.write("# flakes ms_1_thread ms_2_threads (BM_SpeedOfLight)\n")
    for fl, a, b in limit:
        f.write(f"{fl:.0f} {a:.6f} {b:.6f}\n")
print("\n".join(section))

if doc != "none":
    text = open(doc).read().split("\n")
    begin = next(i for i, l in enumerate(text) if l.startswith("<!-- perf.sh begin"))
    end = next(i for i, l in enumerate(text) if l.startswith("<!-- perf.sh end")) if any(
        l.startswith("<!-- perf.sh end") for l in text) else None
    if end is None or end < begin:
        sys.exit(f"[perf] error: {doc} has no '<!-- perf.sh end' marker after the begin marker")
    open(doc, "w").write("\n".join(text[:begin + 1] + [""] + section + text[end:]))
    print(f"[perf] wrote the generated section of {doc}")
EOF

gnuplot <<EOF
set terminal pngcairo size 800,520 font ",11" noenhanced
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
     "$OUT/limit.dat" using 1:2 with points pt 6 ps 1.5 lc rgb "gray" title "BM_SpeedOfLight, 1 thread", \
     "$OUT/limit.dat" using 1:3 with points pt 4 ps 1.5 lc rgb "black" title "BM_SpeedOfLight, 2 threads"
EOF
echo "[perf] wrote $OUT/perf.json, $OUT/tables.md and docs/img/perf_scaling.png"
