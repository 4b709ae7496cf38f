#!/usr/bin/env python3
"""The SLAM bar over many logs and seeds: every scenario (the simulator's
INIs and the independent cross-check simulator's), seeds 1..N, each method
with its stock INI, scored against the ground truth. One JSON line per run
in OUT/runs.jsonl; `table` prints the medians per scenario and method, and
beside another run's results with --vs.

  python3 scripts/bar_eval.py run --out OUT [--bin build/bin] [--seeds 10]
      [--scenarios a,b] [--methods pf,ps,fastslam] [--jobs 2] [--logs DIR]
      [--set S.K=V ...] [--config-dir DIR] [--smooth]
  python3 scripts/bar_eval.py table OUT [--vs OTHER_OUT]
  python3 scripts/bar_eval.py list

A relocation is what rfir-slam's stats.json reports. Kidnap recovery: the
time from the put-down (the largest jump of the ground truth) until the
error stays under max(0.3 m, 2 x the run's median error before it) for 5 s.
Logs are generated once per scenario and seed (in --logs, default OUT/logs)
with the given build's rfir-sim and rfir-import, so that two builds can be
scored on the same logs. Standard library only."""
import argparse, concurrent.futures, json, math, os, statistics, subprocess, sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
XC = os.path.join(ROOT, "scripts", "crosscheck", "textlog_sim.py")

SIM = ["sim_rfid_60mm_16tags_loop", "sim_rfid_60mm_16tags_random",
       "sim_rfid_60mm_100tags_loop", "sim_rfid_60mm_100tags_random",
       "sim_rfid_300mm_4tags_random", "sim_rfid_300mm_4tags_predef1",
       "sim_rfid_300mm_rotation", "sim_rfid_300mm_lawnmower",
       "sim_rfid_60mm_16tags_loop_biased", "sim_rfid_300mm_4tags_random_biased",
       "sim_rb_norotation", "sim_rb_rotation",
       "sim_faults_async", "sim_faults_bias", "sim_faults_combined",
       "sim_faults_combined_300mm", "sim_faults_dead_reader", "sim_faults_ghost",
       "sim_faults_slips", "sim_kidnap", "sim_kidnap_300mm",
       "sim_explore_10x8_40min", "bench_floor_30x20"]
XCS = {
    "xc_loop60": "--layout ring8_60 --density 16 --path loop --area 3x3 --duration 150",
    "xc_async60": "--layout ring8_60 --density 16 --path loop --area 3x3 --duration 150 --async",
    "xc_slow60": "--layout ring8_60 --density 16 --path loop --area 3x3 --duration 150 --async --odom-hz 5",
    "xc_rect4": "--layout grid4_rect --density 16 --path random --area 4x4 --duration 150",
    "xc_line100": "--layout line3 --density 100 --path random --area 3x3 --duration 150",
    "xc_rand300": "--layout ring8_300 --density 4 --path random --area 5x5 --duration 200",
    "xc_spin300": "--layout ring8_300 --density 4 --path random --area 5x5 --duration 200 --omega 0.3",
    "xc_big300": "--layout ring8_300 --density 4 --path random --area 30x20 --duration 200",
    "xc_kid60": "--layout ring8_60 --density 16 --path loop --area 3x3 --duration 200 --kidnap 90",
    "xc_kid300": "--layout ring8_300 --density 4 --path random --area 5x5 --duration 200 --kidnap 100",
    "xc_kidturn60": "--layout ring8_60 --density 16 --path loop --area 3x3 --duration 200 --kidnap 90 --kidnap-turn 1.5",
    "xc_kidturn300": "--layout ring8_300 --density 4 --path random --area 5x5 --duration 200 --kidnap 100 --kidnap-turn 1.5",
    "xc_kidnear60": "--layout ring8_60 --density 16 --path loop --area 3x3 --duration 200 --kidnap 90 --kidnap-dist 0.6 --kidnap-turn 0.3",
    "xc_kidnear300": "--layout ring8_300 --density 4 --path random --area 5x5 --duration 200 --kidnap 100 --kidnap-dist 1.0 --kidnap-turn 0.3",
    "xc_faults60": "--layout ring8_60 --density 16 --path loop --area 3x3 --duration 300 --scale 1.02 --drift 0.005 --slips 3 --dead 2,100,160 --ghost 0.005",
    "xc_faults300": "--layout ring8_300 --density 4 --path random --area 5x5 --duration 300 --scale 1.02 --drift 0.005 --slips 3 --dead 2,100,160 --ghost 0.005",
    "xc_lawn300": "--layout ring8_300 --density 4 --path lawn --area 6x6 --duration 300 --scale 0.98 --drift -0.008 --ghost 0.01",
    "xc_rr60": "--layout ring8_60 --density 16 --path loop --area 3x3 --duration 150 --async --odom-hz 25 --rr-hz 5 --lag 0.02",
    "xc_miss60": "--layout ring8_60 --density 16 --path loop --area 3x3 --duration 150 --miss 0.3",
    "xc_miss300": "--layout ring8_300 --density 4 --path random --area 5x5 --duration 200 --miss 0.3 --ghost 0.02",
    "xc_explore60": "--layout ring8_60 --density 16 --path random --area 10x8 --duration 2400",
}
ALL = SIM + list(XCS)


def sh(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        raise RuntimeError(" ".join(cmd) + "\n" + r.stderr[-2000:])
    return r


def make_log(binDir, logs, sc, seed):
    d = os.path.join(logs, sc, f"s{seed}")
    rawlog = os.path.join(d, sc + ".rawlog")
    if os.path.exists(rawlog):
        return d, rawlog
    os.makedirs(d, exist_ok=True)
    if sc in XCS:
        prefix = os.path.join(d, sc)
        sh([sys.executable, XC, "--out", prefix, "--seed", str(seed)] + XCS[sc].split())
        sh([os.path.join(binDir, "rfir-import"), "--input", prefix + ".txt", "--output",
            prefix + ".part.rawlog", "-q"])
        os.replace(prefix + ".part.rawlog", rawlog + ".part")
    else:
        tmp = d + ".sim"
        sh([os.path.join(binDir, "rfir-sim"), "--config",
            os.path.join(ROOT, "config_ini", sc + ".ini"), "--out-dir", tmp, "--seed",
            str(seed), "-q"])
        for f in os.listdir(tmp):
            os.replace(os.path.join(tmp, f), os.path.join(d, f))
        os.rmdir(tmp)
        os.replace(rawlog, rawlog + ".part")
    os.replace(rawlog + ".part", rawlog)
    return d, rawlog


def read_tum(path):
    out = []
    with open(path) as f:
        for line in f:
            v = line.split()
            if len(v) == 8 and not line.startswith("#"):
                out.append((float(v[0]), float(v[1]), float(v[2])))
    return out


def recovery(path, gt):
    """(put-down time, seconds to recover) or None without a kidnapping."""
    jumps = [(math.hypot(gt[i][1] - gt[i - 1][1], gt[i][2] - gt[i - 1][2]), i)
             for i in range(1, len(gt))]
    if not jumps:
        return None
    j, i = max(jumps)
    if j < 0.25:
        return None
    down = gt[i][0]
    g = {round(p[0], 3): p for p in gt}
    err = [(t, math.hypot(x - g[round(t, 3)][1], y - g[round(t, 3)][2]))
           for t, x, y in path if round(t, 3) in g]
    before = [e for t, e in err if t < down - 1]
    bound = max(0.3, 2 * statistics.median(before)) if before else 0.3
    after = [(t, e) for t, e in err if t >= down]
    for k, (t, e) in enumerate(after):
        if e >= bound:
            continue
        ok = True
        for t2, e2 in after[k:]:
            if t2 > t + 5:
                break
            if e2 >= bound:
                ok = False
                break
        if ok:
            return down, t - down
    return down, math.inf


def run_one(binDir, logs, out, sc, seed, method, sets, cfgdir, smooth):
    d, rawlog = make_log(binDir, logs, sc, seed)
    od = os.path.join(out, "runs", sc, f"s{seed}", method)
    os.makedirs(od, exist_ok=True)
    cmd = [os.path.join(binDir, "rfir-slam"), "--rawlog", rawlog, "--method", method,
           "--seed", str(seed), "--out-dir", od, "-q",
           "--gt-path", os.path.join(d, sc + ".gt.tum")]
    if cfgdir:
        cmd += ["--config", os.path.join(cfgdir, f"slam_{method}.ini")]
    if smooth and method != "fastslam":
        cmd += ["--smooth"]
    for s in sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, capture_output=True, text=True)
    rec = {"scenario": sc, "seed": seed, "method": method}
    if r.returncode != 0:
        rec["error"] = r.stderr[-500:]
        return rec
    st = json.load(open(os.path.join(od, "stats.json")))
    ev = json.load(open(os.path.join(od, "errors.json")))
    rec.update(mean=ev["robot"]["mean_dist"], max=ev["robot"]["max_dist"],
               odo=ev["dead_reckoning"]["mean_dist"], odo_max=ev["dead_reckoning"]["max_dist"],
               tags=(ev.get("tags") or {}).get("mean_dist"),
               relocations=st.get("relocations", st.get("kidnap_resets", 0)),
               reloc_times=st.get("relocation_times_s", st.get("kidnap_reset_times_s", [])),
               time=st.get("total_time_s"))
    if smooth and os.path.exists(os.path.join(od, "errors_smoothed.json")):
        es = json.load(open(os.path.join(od, "errors_smoothed.json")))
        rec["smoothed"] = es["robot"]["mean_dist"]
    rv = recovery(read_tum(os.path.join(od, "path.tum")),
                  read_tum(os.path.join(d, sc + ".gt.tum")))
    if rv:
        rec["kidnap_at"], rec["recovery"] = rv
    return rec


def cmd_run(a):
    scen = a.scenarios.split(",") if a.scenarios else ALL
    for s in scen:
        if s not in ALL:
            sys.exit(f"bar_eval.py: unknown scenario '{s}' (see: list)")
    os.makedirs(a.out, exist_ok=True)
    logs = a.logs or os.path.join(a.out, "logs")
    # Logs first (one process per log), then the runs.
    jobs = [(sc, s) for sc in scen for s in range(1, a.seeds + 1)]
    with concurrent.futures.ProcessPoolExecutor(a.jobs) as ex:
        list(ex.map(make_log, [a.bin] * len(jobs), [logs] * len(jobs),
                    [j[0] for j in jobs], [j[1] for j in jobs]))
    runs = [(sc, s, m) for sc, s in jobs for m in a.methods.split(",")]
    done = 0
    with open(os.path.join(a.out, "runs.jsonl"), "a") as f, \
            concurrent.futures.ProcessPoolExecutor(a.jobs) as ex:
        futs = [ex.submit(run_one, a.bin, logs, a.out, sc, s, m, a.set or [], a.config_dir,
                          a.smooth) for sc, s, m in runs]
        for fu in concurrent.futures.as_completed(futs):
            rec = fu.result()
            f.write(json.dumps(rec) + "\n")
            f.flush()
            done += 1
            if done % 20 == 0:
                print(f"bar_eval.py: {done}/{len(runs)} runs", file=sys.stderr)


def load(out):
    recs = {}
    with open(os.path.join(out, "runs.jsonl")) as f:
        for line in f:
            r = json.loads(line)
            recs[(r["scenario"], r["seed"], r["method"])] = r
    return recs


def summary(recs):
    by = {}
    for (sc, seed, m), r in recs.items():
        by.setdefault((sc, m), []).append(r)
    res = {}
    for k, rs in by.items():
        ok = [r for r in rs if "error" not in r]
        s = {"n": len(ok), "errors": len(rs) - len(ok)}
        if ok:
            s["mean"] = statistics.median(r["mean"] for r in ok)
            s["odo"] = statistics.median(r["odo"] for r in ok)
            s["reloc"] = sum(r["relocations"] for r in ok)
            rec = [r["recovery"] for r in ok if "recovery" in r]
            if rec:
                s["rec_ok"] = sum(1 for v in rec if v <= 5)
                s["rec_n"] = len(rec)
            sm = [r["smoothed"] for r in ok if "smoothed" in r]
            if sm:
                s["smoothed"] = statistics.median(sm)
        res[k] = s
    return res


def cell(s):
    if not s or not s.get("n"):
        return "-"
    t = f"{1000 * s['mean']:.0f}"
    if s.get("reloc"):
        t += f" r{s['reloc']}"
    if "rec_n" in s:
        t += f" k{s['rec_ok']}/{s['rec_n']}"
    if "smoothed" in s:
        t += f" sm{1000 * s['smoothed']:.0f}"
    if s.get("errors"):
        t += f" E{s['errors']}"
    return t


def cmd_table(a):
    A = summary(load(a.out))
    B = summary(load(a.vs)) if a.vs else None
    methods = sorted({m for _, m in A}, key=["pf", "ps", "fastslam", "odometry"].index)
    scen = [s for s in ALL if any((s, m) in A for m in methods)]
    hdr = "| scenario | odometry | " + " | ".join(methods) + " |"
    print("Median robot mean error over the random seeds, mm (rN: relocations summed "
          "over the random seeds; kA/B: kidnappings recovered within 5 s; sm: smoothed)" +
          (f"; each cell this / {a.vs}" if B else ""))
    print()
    print(hdr)
    print("|" + " --- |" * (len(methods) + 2))
    for sc in scen:
        odo = next((A[(sc, m)]["odo"] for m in methods if A.get((sc, m), {}).get("n")), None)
        row = [sc, f"{1000 * odo:.0f}" if odo is not None else "-"]
        for m in methods:
            c = cell(A.get((sc, m)))
            if B is not None:
                c += " / " + cell(B.get((sc, m)))
            row.append(c)
        print("| " + " | ".join(row) + " |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("--out", required=True)
    r.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    r.add_argument("--seeds", type=int, default=10)
    r.add_argument("--scenarios", default="")
    r.add_argument("--methods", default="pf,ps,fastslam")
    r.add_argument("--jobs", type=int, default=2)
    r.add_argument("--logs", default="")
    r.add_argument("--set", action="append")
    r.add_argument("--config-dir", default="")
    r.add_argument("--smooth", action="store_true")
    t = sub.add_parser("table")
    t.add_argument("out")
    t.add_argument("--vs", default="")
    sub.add_parser("list")
    a = ap.parse_args()
    if a.cmd == "run":
        cmd_run(a)
    elif a.cmd == "table":
        cmd_table(a)
    else:
        print("\n".join(ALL))


if __name__ == "__main__":
    main()
