"""The Python module against the programs: the same INI and seed give the
same files, byte for byte (ctest python_module; tests/python.cmake).
    test_rfir.py BIN_DIR SOURCE_DIR WORK_DIR  (rfir importable: PYTHONPATH)"""
import json
import os
import shutil
import subprocess
import sys
import threading
import time
import unittest

import numpy as np

import rfir

BIN, SRC, WORK = sys.argv[1:4]
DATA = os.path.join(SRC, "datasets")
RFID = os.path.join(DATA, "rfid_300mm_4tags_random_90s")
IR = os.path.join(DATA, "ir_raw_15s")


def program(name, *args):
    """Runs build/bin/<name>; returns its stdout (fails the test on a non-zero exit)."""
    p = subprocess.run([os.path.join(BIN, name), *args], capture_output=True, text=True)
    if p.returncode != 0:
        raise AssertionError("%s failed (%d): %s" % (name, p.returncode, p.stderr))
    return p.stdout


def read(path, mode="rb"):
    with open(path, mode) as f:
        return f.read()


def without_times(stats):
    """stats.json without what differs between any two runs: wall-clock times
    and the run's identity (command line, files)."""
    return {k: v for k, v in stats.items()
            if "time" not in k and "seconds" not in k and k != "run"}


class Work(unittest.TestCase):
    def setUp(self):
        self.dir = os.path.join(WORK, self.id().split(".")[-1])
        shutil.rmtree(self.dir, ignore_errors=True)
        os.makedirs(self.dir)

    def out(self, name):
        return os.path.join(self.dir, name)


class Slam(Work):
    def check_method(self, config, seed):
        program("rfir-slam", "--rawlog", RFID + ".rawlog", "--config", config,
                "--seed", str(seed), "--out-dir", self.out("prog"), "-q")
        r = rfir.slam(RFID + ".rawlog", config=config, seed=seed, out_dir=self.out("py"))
        prog = self.out("prog")
        # The files the module writes are the program's, byte for byte ...
        for f in ("path.tum", "map.txt", "errors.json"):
            self.assertEqual(read(os.path.join(prog, f)), read(self.out("py/" + f)), f)
        # ... and so are the values it returns.
        rfir.save_tum(r.path, self.out("mem.tum"))
        self.assertEqual(read(os.path.join(prog, "path.tum")), read(self.out("mem.tum")))
        self.assertEqual(r.path.shape[1], 4)
        rfir.save_map(r.landmarks, self.out("mem_map.txt"))
        self.assertEqual(rfir.load_map(os.path.join(prog, "map.txt")).entries,
                         rfir.load_map(self.out("mem_map.txt")).entries)
        self.assertEqual(r.landmarks.ids, rfir.load_map(os.path.join(prog, "map.txt")).ids)
        self.assertFalse(np.isnan(r.landmarks.std).any())
        stats = json.loads(read(os.path.join(prog, "stats.json"), "r"))
        self.assertEqual(without_times(r.stats), without_times(stats))
        self.assertEqual(r.stats["steps"], len(r.path))
        self.assertEqual(r.errors, json.loads(read(os.path.join(prog, "errors.json"), "r")))
        return r

    def test_ps_equals_rfir_slam(self):
        self.check_method("slam_ps", 1)

    def test_pf_equals_rfir_slam(self):
        r = self.check_method("slam_pf", 7)
        # The seed matters (else the comparison above could not tell seeds apart).
        other = rfir.slam(RFID + ".rawlog", config="slam_pf", seed=8)
        self.assertFalse(np.array_equal(r.path, other.path))
        again = rfir.slam(RFID + ".rawlog", config="slam_pf", seed=7)
        self.assertTrue(np.array_equal(r.path, again.path))

    def test_smooth_equals_rfir_slam(self):
        program("rfir-slam", "--rawlog", RFID + ".rawlog", "--config", "slam_ps",
                "--smooth", "--out-dir", self.out("prog"), "-q")
        r = rfir.slam(RFID + ".rawlog", config="slam_ps", smooth=True)
        rfir.save_tum(r.smoothed_path, self.out("mem.tum"))
        self.assertEqual(read(self.out("prog/path_smoothed.tum")), read(self.out("mem.tum")))
        rfir.save_map(r.smoothed_landmarks, self.out("mem_map.txt"))  # as printed
        self.assertEqual(rfir.load_map(self.out("mem_map.txt")).entries,
                         rfir.load_map(self.out("prog/map_smoothed.txt")).entries)
        self.assertEqual(r.smoothed_errors,
                         json.loads(read(self.out("prog/errors_smoothed.json"), "r")))
        self.assertEqual(r.stats["smoother"]["iterations"],
                         json.loads(read(self.out("prog/stats.json"), "r"))["smoother"]["iterations"])

    def test_sets_and_ini_file(self):
        ini = os.path.join(SRC, "config_ini", "slam_pf.ini")
        sets = ["slam.robot_particles=20"]
        program("rfir-slam", "--rawlog", RFID + ".rawlog", "--config", ini, "--set",
                sets[0], "--seed", "3", "--out-dir", self.out("prog"), "-q")
        r = rfir.slam(RFID + ".rawlog", config=ini, sets=sets, seed=3)
        rfir.save_tum(r.path, self.out("mem.tum"))
        self.assertEqual(read(self.out("prog/path.tum")), read(self.out("mem.tum")))
        self.assertEqual(r.stats["robot_particles"], 20)

    def test_errors_name_the_cause(self):
        with self.assertRaisesRegex(ValueError, "robot_particlez"):
            rfir.slam(RFID + ".rawlog", config="slam_pf", sets=["slam.robot_particlez=3"])
        with self.assertRaisesRegex(RuntimeError, "no_such.rawlog"):
            rfir.slam(self.out("no_such.rawlog"))
        with self.assertRaisesRegex(ValueError, "slam_nope.*stock: .*slam_ps"):
            rfir.slam(RFID + ".rawlog", config="slam_nope")

    def test_gil_released_during_the_run(self):
        """The main thread runs while rfir.slam works in another: its longest
        pause is well under the run's time (it would be the whole run with
        the GIL held)."""
        done = []
        t = threading.Thread(target=lambda: done.append(
            rfir.slam(RFID + ".rawlog", config="slam_pf", seed=1)))
        t0 = time.monotonic()
        last, gap = t0, 0.0
        t.start()
        while t.is_alive():
            now = time.monotonic()
            gap, last = max(gap, now - last), now
        t.join()
        total = time.monotonic() - t0
        self.assertTrue(done)
        self.assertLess(gap, 0.5 * total, "longest pause %.3f s of %.3f s" % (gap, total))

    def test_concurrent_runs_are_the_sequential_ones(self):
        """Runs in threads at once (the GIL released) give the paths of the
        same runs one after the other."""
        seeds = (7, 8, 9)
        alone = [rfir.slam(RFID + ".rawlog", config="slam_pf", seed=s).path for s in seeds]
        together = {}

        def run(s):
            together[s] = rfir.slam(RFID + ".rawlog", config="slam_pf", seed=s).path

        threads = [threading.Thread(target=run, args=(s,)) for s in seeds]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        for s, p in zip(seeds, alone):
            self.assertTrue(np.array_equal(together[s], p), "seed %d" % s)


class Localize(Work):
    def test_equals_rfir_localize(self):
        em = IR + ".gt_map.txt"
        program("rfir-localize", "--rawlog", IR + ".rawlog", "--emitters", em,
                "--seed", "3", "--out-dir", self.out("prog"), "-q")
        r = rfir.localize(IR + ".rawlog", emitters=em, seed=3, out_dir=self.out("py"))
        for f in ("path.tum", "errors.json", "emitter_health.txt"):
            self.assertEqual(read(self.out("prog/" + f)), read(self.out("py/" + f)), f)
        rfir.save_tum(r.path, self.out("mem.tum"))
        self.assertEqual(read(self.out("prog/path.tum")), read(self.out("mem.tum")))
        stats = json.loads(read(self.out("prog/stats.json"), "r"))
        self.assertEqual(without_times(r.stats), without_times(stats))
        self.assertEqual(r.errors, json.loads(read(self.out("prog/errors.json"), "r")))
        self.assertGreater(len(r.path), 0)

    def test_errors_name_the_cause(self):
        with self.assertRaisesRegex(RuntimeError, "emitter_file"):
            rfir.localize(IR + ".rawlog")  # the stock INI names no emitter file
        with self.assertRaisesRegex(ValueError, "localization.num_particlez"):
            rfir.localize(IR + ".rawlog", emitters=IR + ".gt_map.txt",
                          sets=["localization.num_particlez=3"])


class Evaluate(Work):
    def test_equals_rfir_eval(self):
        program("rfir-slam", "--rawlog", RFID + ".rawlog", "--config", "slam_ps",
                "--out-dir", self.out("run"), "-q")
        args = dict(gt_path=RFID + ".gt.tum", gt_map=RFID + ".gt_map.txt",
                    rawlog=RFID + ".rawlog")
        program("rfir-eval", "--path", self.out("run/path.tum"), "--map",
                self.out("run/map.txt"), "--gt-path", args["gt_path"], "--gt-map",
                args["gt_map"], "--rawlog", args["rawlog"], "--json-file",
                self.out("eval.json"), "-q")
        expected = json.loads(read(self.out("eval.json"), "r"))
        got = rfir.evaluate(self.out("run/path.tum"), map=self.out("run/map.txt"), **args)
        self.assertEqual(got, expected)
        self.assertIn("rmse_dist", got["robot"])
        # A result is scored from its path and map as written.
        r = rfir.slam(RFID + ".rawlog", config="slam_ps")
        self.assertEqual(rfir.evaluate(r, **args), expected)


class Logs(Work):
    def test_import_export_equal_rfir_import(self):
        txt = os.path.join(DATA, "tutorial_robot.txt")
        program("rfir-import", "-i", txt, "-o", self.out("prog.rawlog"), "-q")
        rep = rfir.import_textlog(txt, self.out("py.rawlog"))
        self.assertEqual(read(self.out("prog.rawlog")), read(self.out("py.rawlog")))
        log = rfir.read_textlog(txt)
        self.assertEqual(rep["timed_records"], len(log.records))
        self.assertIn("reader R0", log.header)
        program("rfir-import", "-i", self.out("prog.rawlog"), "-o", self.out("prog.txt"), "-q")
        rfir.export_textlog(self.out("py.rawlog"), self.out("py.txt"))
        self.assertEqual(read(self.out("prog.txt")), read(self.out("py.txt")))

    def test_bad_line_named(self):
        bad = self.out("bad.txt")
        with open(bad, "w") as f:
            f.write(read(os.path.join(DATA, "tutorial_robot.txt"), "r")
                    .replace("rfid 3 R1", "rfid 3 R7"))
        with self.assertRaisesRegex(RuntimeError, r"bad\.txt:\d+: .*'R7'"):
            rfir.import_textlog(bad, self.out("bad.rawlog"))
        self.assertFalse(os.path.exists(self.out("bad.rawlog")))


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
