#!/usr/bin/python3
"""The shared dense benchmark ("plate compression", ../shared/bench/README.md)
run by this engine and by its peer, LIGGGHTS 3.8 (Debian's `liggghts`), on
the same packing, on the same machine, in one run.

For each size and each thread / rank count the two codes take turns
(ours, LIGGGHTS, ours, LIGGGHTS, ...) so that a machine that speeds up or
slows down during the run affects both alike; each keeps its best of the
repeats. Printed for every row: particle-steps/s of both and their ratio,
contacts per particle and plate force of both, and peak RSS of both
(for two ranks, the sum over the ranks). Before and after the runs it
measures the round trip of a cache line between the two cores
(bench/core_round_trip): on shared virtual machines it changes by 4x over
hours, and two threads' speed-up with it (docs/PERFORMANCE.md).

  bench/peer_comparison.py [--sizes 10k,100k] [--threads 1,2] [--repeats 2]
                           [--builds build[,build-v3]] [--materials one[,many]]
                           [--million] [--markdown FILE]

--builds puts several builds of this engine in the same run (say one for
x86-64-v4 and one configured with -DDEM_ARCH=x86-64-v3, docs/INSTALL.md),
--materials several material mixes of bench_plate_compression (the same
physics with the walls' and particles' materials copied): each build and
mix is a column of its own, with its ratio to LIGGGHTS, all taking turns
with it.

--million also runs this engine on a 1,000,000-sphere bed: ten copies of
the 100k periodic packing side by side along x (a 1.0 m x 0.1 m periodic
footprint, the same height), with one and then every thread count.

Installs what it needs (liggghts, openmpi-bin, numpy, scipy, time) when
run as root. Needs a build of bench_plate_compression (scripts/build.sh).
"""
import argparse
import datetime
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SHARED = ROOT.parent / "shared" / "bench"
PEERS = SHARED / "peers"
PACKAGES = ["liggghts", "openmpi-bin", "python3-numpy", "python3-scipy", "time"]
SIZES = {"10k": 10000, "100k": 100000}
# Plate start heights from the benchmark definition (README: z0 = max(z + r) + 20 um).
PLATE_Z0 = {"10k": 0.035725498554771126, "100k": 0.07298219427101427}
MPI_ENV = {"OMPI_MCA_btl": "self,vader", "OMPI_MCA_oob_tcp_if_include": "lo", "OMPI_ALLOW_RUN_AS_ROOT": "1",
           "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1", "OMPI_MCA_rmaps_base_oversubscribe": "1"}


def install_packages():
    missing = [p for p in PACKAGES
               if subprocess.run(["dpkg-query", "-W", "-f=${Status}", p], capture_output=True, text=True)
               .stdout.find("install ok installed") < 0]
    if not missing:
        return
    if os.geteuid() != 0:
        sys.exit(f"peer_comparison: missing packages {' '.join(missing)} (run as root to install them)")
    print(f"peer_comparison: installing {' '.join(missing)}", flush=True)
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(["apt-get", "update", "-qq"], check=True, env=env)
    subprocess.run(["apt-get", "install", "-y", "-qq", "--no-install-recommends", *missing], check=True, env=env,
                   stdout=subprocess.DEVNULL)


def run_timed(command, env=None, cwd=None):
    """Runs a command under /usr/bin/time; returns (stdout, peak RSS in MiB summed over every 'RSS' line)."""
    result = subprocess.run(command, capture_output=True, text=True, env=env, cwd=cwd)
    if result.returncode != 0:
        sys.exit(f"peer_comparison: {' '.join(map(str, command))} failed ({result.returncode}):\n"
                 f"{result.stdout[-2000:]}\n{result.stderr[-2000:]}")
    rss_kib = sum(int(m) for m in re.findall(r"^PEAK_RSS_KIB (\d+)$", result.stderr, re.M))
    return result.stdout, rss_kib / 1024.0


TIME = ["/usr/bin/time", "-f", "PEAK_RSS_KIB %M"]


def case_file(size):
    """The benchmark's case for a size ("10k", "100k")."""
    return ROOT / "cases" / "bench" / f"plate_compression_{size}.case.txtpb"


def bench_rate(out):
    """Particle-steps per second from bench_plate_compression's output."""
    return float(re.search(r"([0-9.e+]+) particle-steps/s", out).group(1))


class Ours:
    def __init__(self, build, materials="one"):
        self.program = build / "bench" / "bench_plate_compression"
        if not self.program.exists():
            sys.exit(f"peer_comparison: {self.program} not found: build first (bash scripts/build.sh)")
        self.materials = materials
        self.label = f"{build_level(build)}" + ("" if materials == "one" else f", materials {materials}")

    def run(self, case, threads):
        env = dict(os.environ, OMP_WAIT_POLICY="active")
        out, rss = run_timed([*TIME, str(self.program), "--case", str(case), "--threads", str(threads),
                              "--materials", self.materials], env=env)
        return {"rate": bench_rate(out), "cpp": float(re.search(r"contacts/particle ([0-9.]+)", out).group(1)),
                "fz": float(re.search(r"plate Fz ([0-9.e+-]+) N", out).group(1)), "rss": rss, "text": out}


class Liggghts:
    def __init__(self, work):
        self.work = work
        self.data = {}

    def prepare(self, size):
        data = self.work / f"N{SIZES[size]}.data"
        stl = self.work / f"plate_N{SIZES[size]}.stl"  # each size has its own plate: footprint and height differ
        if not (data.exists() and stl.exists()):
            subprocess.run(["/usr/bin/python3", str(PEERS / "packing.py"), "csv2data",
                            str(SHARED / f"packing_N{SIZES[size]}.csv"), str(data), "--gap", "2e-5", "--stl", str(stl)],
                           check=True, stdout=subprocess.DEVNULL)
        self.data[size] = (data, stl)

    def run(self, size, ranks):
        data, stl = self.data[size]
        log = self.work / f"log_{size}_{ranks}.txt"
        env = dict(os.environ, **MPI_ENV)
        # Each rank's /usr/bin/time appends its own line to one file: on the
        # shared stderr two ranks' lines interleave mid-line.
        rss_file = self.work / f"rss_{size}_{ranks}.txt"
        rss_file.unlink(missing_ok=True)
        time = ["/usr/bin/time", "-a", "-o", str(rss_file), "-f", "PEAK_RSS_KIB %M"]
        command = ["mpirun", "-np", str(ranks), "--bind-to", "none", *time, "liggghts",
                   "-in", str(PEERS / "in.plate.liggghts"), "-var", "data", str(data), "-var", "stl", str(stl),
                   "-var", "z0", repr(PLATE_Z0[size]), "-var", "nwarm", "200", "-var", "nrun", "2000",
                   "-var", "final", str(self.work / "final.dump"), "-log", str(log)]  # (-screen none crashes LIGGGHTS 3.8 reading the STL)
        run_timed(command, env=env, cwd=self.work)
        rss = sum(int(m) for m in re.findall(r"^PEAK_RSS_KIB (\d+)$", rss_file.read_text(), re.M)) / 1024.0
        text = log.read_text()
        loops = re.findall(r"^Loop time of ([0-9.e+-]+) on", text, re.M)
        timed = float(loops[1])  # the second run: the 2000 timed steps
        pairs = float(re.search(r"^DENSE_CONTACTS_PP ([0-9.e+-]+)", text, re.M).group(1))
        return {"rate": SIZES[size] * 2000 / timed, "cpp": 2.0 * pairs / SIZES[size],
                "fz": float(re.search(r"^DENSE_PLATE_FZ ([0-9.e+-]+)", text, re.M).group(1)), "rss": rss}


def build_level(build):
    """The instruction set a build was configured for (its DEM_ARCH; "auto" resolved as CMake did)."""
    cache = build / "CMakeCache.txt"
    text = cache.read_text() if cache.exists() else ""
    arch = re.search(r"^DEM_ARCH:STRING=(.*)$", text, re.M)
    arch = arch.group(1) if arch else "auto"
    if arch == "auto":
        arch = "x86-64-v4" if re.search(r"^DEM_ARCH_SUPPORTED_x86-64-v4:INTERNAL=1$", text, re.M) else "x86-64-v3"
    return arch


def best(runs):
    """The fastest run's figures (physics is identical between repeats)."""
    return max(runs, key=lambda r: r["rate"])


def million_case(work):
    """Ten copies of the 100k packing along x: 1,000,000 spheres, periodic over 1.0 m x 0.1 m."""
    csv = work / "packing_N1000000.csv"
    if not csv.exists():
        source = SHARED / "packing_N100000.csv"
        rows = [line for line in source.read_text().splitlines() if line and not line.startswith("#")][1:]
        with csv.open("w") as f:
            f.write("# ten copies of packing_N100000.csv along x (bench/peer_comparison.py)\nx,y,z,r\n")
            for copy in range(10):
                shift = 0.1 * copy
                for row in rows:
                    x, rest = row.split(",", 1)
                    f.write(f"{float(x) + shift!r},{rest}\n")
    case = case_file("100k").read_text()
    case = case.replace('name: "plate_compression_100k"', 'name: "plate_compression_1m"')
    case = case.replace("100000 spheres", "1000000 spheres (ten copies of the 100k bed along x)")
    case = re.sub(r'path: "[^"]*"', f'path: "{csv}"', case)
    case = case.replace("max { x: 0.1 y: 0.1 }", "max { x: 1.0 y: 0.1 }")
    case = case.replace("point { x: 0.05 y: 0.05", "point { x: 0.5 y: 0.05")
    path = work / "plate_compression_1m.case.txtpb"
    path.write_text(case)
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", default="10k,100k")
    parser.add_argument("--threads", default="1,2")
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--million", action="store_true", help="also run this engine on 1,000,000 spheres")
    parser.add_argument("--build", type=Path, default=ROOT / "build", help="the build whose core_round_trip runs")
    parser.add_argument("--builds", help="builds of this engine side by side, comma-separated (default: --build)")
    parser.add_argument("--materials", default="one", help="material mixes side by side: one, walls, particles, few, many")
    parser.add_argument("--work", type=Path, default=ROOT / "build" / "peer_comparison")
    parser.add_argument("--markdown", type=Path, help="also write the table here (Markdown)")
    args = parser.parse_args()
    sizes = args.sizes.split(",")
    threads = [int(t) for t in args.threads.split(",")]

    install_packages()
    args.work.mkdir(parents=True, exist_ok=True)
    builds = [Path(b) for b in args.builds.split(",")] if args.builds else [args.build]
    variants = [Ours(b, m) for b in builds for m in args.materials.split(",")]
    ours, peer = variants[0], Liggghts(args.work)
    round_trips = [core_round_trip(args.build)]
    rows, side_rows = [], []
    for size in sizes:
        peer.prepare(size)
        case = case_file(size)
        for t in threads:
            runs_ours, runs_peer = [[] for _ in variants], []
            for r in range(args.repeats):
                for runs, variant in zip(runs_ours, variants):
                    runs.append(variant.run(case, t))
                runs_peer.append(peer.run(size, t))
                print(f"  {size} {t} thread(s)/rank(s), repeat {r + 1}: "
                      + ", ".join(f"ours ({v.label}) {runs[-1]['rate'] / 1e6:.2f} M/s" for v, runs in zip(variants, runs_ours))
                      + f", LIGGGHTS {runs_peer[-1]['rate'] / 1e6:.2f} M/s", flush=True)
            rows.append((size, t, best(runs_ours[0]), best(runs_peer)))
            side_rows.append((size, t, [best(runs) for runs in runs_ours], best(runs_peer)))

    million = []
    if args.million:
        case = million_case(args.work)
        for t in threads:
            runs = [ours.run(case, t) for _ in range(args.repeats)]
            million.append((t, best(runs)))
            print(f"  1M {t} thread(s): ours {million[-1][1]['rate'] / 1e6:.2f} M/s", flush=True)

    round_trips.append(core_round_trip(args.build))
    lines = [f"Measured {datetime.date.today().isoformat()} on {os.cpu_count()} cores "
             f"({platform_name()}), best of {args.repeats}, interleaved; a cache line's round trip between "
             f"the cores {round_trips[0]} before the runs, {round_trips[1]} after.", "",
             "| N | threads / ranks | ours (particle-steps/s) | LIGGGHTS | ratio | contacts/particle ours / LIGGGHTS "
             "| plate Fz (N) ours / LIGGGHTS | peak RSS ours / LIGGGHTS |",
             "|---|---|---|---|---|---|---|---|"]
    one_thread = {size: o["rate"] for size, t, o, _ in rows if t == 1}
    for size, t, o, p in rows:
        lines.append(f"| {size} | {t} | {o['rate'] / 1e6:.2f} M | {p['rate'] / 1e6:.2f} M | {o['rate'] / p['rate']:.2f} "
                     f"| {o['cpp']:.4f} / {p['cpp']:.4f} ({100 * (o['cpp'] / p['cpp'] - 1):+.2f} %) "
                     f"| {o['fz']:.5f} / {p['fz']:.5f} ({100 * (o['fz'] / p['fz'] - 1):+.1f} %) "
                     f"| {o['rss']:.0f} MiB / {p['rss']:.0f} MiB |")
    if len(variants) > 1:
        lines += ["", f"Side by side in the same run (the first column is the table's above; {cpu_flags()}):", "",
                  "| N | threads / ranks | " + " | ".join(f"ours, {v.label}" for v in variants) + " | LIGGGHTS |",
                  "|---|---|" + "---|" * (len(variants) + 1)]
        for size, t, results, p in side_rows:
            cells = [f"{o['rate'] / 1e6:.2f} M ({o['rate'] / p['rate']:.2f}x)" for o in results]
            lines.append(f"| {size} | {t} | " + " | ".join(cells) + f" | {p['rate'] / 1e6:.2f} M |")
        differing = [(size, t, v.label) for size, t, results, _ in side_rows for v, o in zip(variants, results)
                     if o["cpp"] != results[0]["cpp"] or o["fz"] != results[0]["fz"]]
        lines.append("\nEvery column's contacts per particle and plate force equal the first's to the printed digit."
                     if not differing else "\nOther physics than the first column's: "
                     + ", ".join(f"{size} {t} ({label})" for size, t, label in differing))
    for size, t, o, _ in rows:
        if t != 1 and one_thread.get(size):
            lines.append(f"\n{size}: {t} threads run at {o['rate'] / one_thread[size]:.2f}x our one-thread rate.")
    if million:
        lines += ["", "| N | threads | ours (particle-steps/s) | contacts/particle | plate Fz (N) | peak RSS |",
                  "|---|---|---|---|---|---|"]
        for t, o in million:
            lines.append(f"| 1M | {t} | {o['rate'] / 1e6:.2f} M | {o['cpp']:.4f} | {o['fz']:.5f} | {o['rss']:.0f} MiB |")
        hundred = {t: o["rate"] for size, t, o, _ in rows if size == "100k"}
        for t, o in million:
            if t in hundred:
                lines.append(f"\n1M against 100k, {t} thread(s): {o['rate'] / hundred[t]:.2f} of the per-particle rate.")
    table = "\n".join(lines)
    print(table)
    if args.markdown:
        args.markdown.write_text(table + "\n")


def core_round_trip(build):
    """The round trip between cores 0 and 1 as text ("97 ns"), or why there is none."""
    program = build / "bench" / "core_round_trip"
    if (os.cpu_count() or 1) < 2 or not program.exists():
        return "not measured"
    out = subprocess.run([str(program)], capture_output=True, text=True).stdout
    found = re.search(r": ([0-9]+ ns)", out)
    return found.group(1) if found else "not measured"


def cpu_flags():
    """The vector instruction sets /proc/cpuinfo lists, as text."""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("flags"):
                have = set(line.split(":", 1)[1].split())
                wanted = ["avx2", "fma", "avx512f", "avx512vl", "avx512bw", "avx512dq", "avx512cd"]
                return "flags " + " ".join(f for f in wanted if f in have)
    except OSError:
        pass
    return "flags unknown"


def platform_name():
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


if __name__ == "__main__":
    main()
