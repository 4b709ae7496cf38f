"""rfir in Python: the programs' runs in-process (docs/python.md).

    import rfir
    res = rfir.slam("run.rawlog", config="slam_ps", seed=1)
    res.path          # n x 4 numpy array: t, x, y, phi (the poses of path.tum)
    res.landmarks     # the map: ids, kinds, xy, std (and reads for PF/PS-SLAM)
    res.stats         # stats.json as a dict
    rfir.evaluate(res, "run.gt.tum", gt_map="run.gt_map.txt")  # rfir-eval's JSON

Each run calls the same library functions as its program (rfir-slam,
rfir-localize, rfir-eval, rfir-import): the same INI and seed give the same
numbers. C++ errors arrive as exceptions with the program's message
(ValueError for what would be a command-line error, else RuntimeError).
"""

import json as _json
import os as _os
import tempfile as _tempfile
from dataclasses import dataclass as _dataclass, field as _field
from pathlib import Path as _Path

import numpy as _np

from . import _rfir
from ._rfir import export_textlog, import_textlog, load_tum, save_tum

__version__ = _rfir.__version__
UsageError = _rfir.UsageError

__all__ = ["slam", "localize", "evaluate", "import_textlog", "export_textlog",
           "read_textlog", "load_tum", "save_tum", "load_map", "save_map",
           "Landmarks", "SlamResult", "LocalizeResult", "TextLog", "UsageError",
           "stock_config_dir"]


def _find_stock_dir():
    """share/rfir/config_ini of the prefix (or build tree) holding this package:
    the programs find theirs beside their own folder, this module beside its."""
    for parent in _Path(__file__).resolve().parents:
        d = parent / "share" / "rfir" / "config_ini"
        if d.is_dir():
            return str(d)
    return None


_STOCK = _find_stock_dir()
if _STOCK:
    _rfir._set_stock_config_dir(_STOCK)


def stock_config_dir():
    """The folder of the stock INIs (share/rfir/config_ini)."""
    return _rfir._stock_config_dir()


def _config_path(config, prefix):
    """An INI file, or a stock INI by name ("slam_ps", "ir_localize"), as the
    programs' --config reads it; None: the program's default."""
    if config is None:
        return ""
    config = _os.fspath(config)
    if _os.path.isfile(config):
        return config
    stock = _os.path.join(stock_config_dir(), config + ("" if config.endswith(".ini") else ".ini"))
    if _os.path.isfile(stock):
        return stock
    names = sorted(f[:-4] for f in _os.listdir(stock_config_dir())
                   if f.startswith(prefix) and f.endswith(".ini"))
    raise UsageError("config: '%s' is no INI file and no stock INI (stock: %s)"
                     % (config, ", ".join(names)))


@_dataclass
class Landmarks:
    """A map: one entry per tag, landmark or emitter, in map.txt's order."""
    ids: list
    kinds: list
    xy: _np.ndarray        #: n x 2 positions (m)
    std: _np.ndarray       #: n x 2 standard deviations sx, sy (m); NaN if none
    reads: list            #: PF/PS-SLAM: reads per tag (None where not counted)
    contradicted: list     #: of which the estimate at the time contradicted
    entries: list = _field(repr=False)  #: the records as dicts (save_map's input)

    def __len__(self):
        return len(self.ids)

    @classmethod
    def from_entries(cls, entries):
        nan = float("nan")
        return cls(
            ids=[e["id"] for e in entries], kinds=[e["kind"] for e in entries],
            xy=_np.array([[e["x"], e["y"]] for e in entries], dtype=float).reshape(-1, 2),
            std=_np.array([[nan if e["sx"] is None else e["sx"],
                            nan if e["sy"] is None else e["sy"]] for e in entries],
                          dtype=float).reshape(-1, 2),
            reads=[e["reads"] for e in entries],
            contradicted=[e["contradicted"] for e in entries], entries=entries)


@_dataclass
class SlamResult:
    """rfir.slam's run: what path.tum, map.txt, stats.json and errors.json hold."""
    path: _np.ndarray      #: n x 4: t, x, y, phi
    landmarks: Landmarks
    stats: dict            #: stats.json (its run.files empty without out_dir)
    errors: dict = None    #: errors.json (None without ground truth)
    error_table: str = ""  #: the table rfir-slam prints
    smoothed_path: _np.ndarray = None
    smoothed_landmarks: Landmarks = None
    smoothed_errors: dict = None


@_dataclass
class LocalizeResult:
    """rfir.localize's run: path.tum, the dead reckoning, stats.json, errors.json."""
    path: _np.ndarray
    odometry: _np.ndarray  #: dead reckoning from the start pose, n x 4
    stats: dict
    errors: dict = None
    error_table: str = ""


def _json_or_none(text):
    return _json.loads(text) if text else None


def _opt(p):
    return None if p is None else _os.fspath(p)


def slam(log, config=None, seed=1, method=None, sets=(), start=None, gt_path=None,
         gt_map=None, smooth=False, out_dir=None, quiet=True):
    """rfir-slam on a rawlog, in-process. `config`: an INI file or a stock INI
    by name (default: the method's stock INI); `sets`: "section.key=value"
    edits (--set); `start`: (x, y, phi); ground truth beside the rawlog is
    found as rfir-slam finds it; `out_dir`: also write rfir-slam's files."""
    r = _rfir._slam(_os.fspath(log), _config_path(config, "slam_"), method, int(seed),
                    list(sets), None if start is None else [float(v) for v in start],
                    _opt(gt_path), _opt(gt_map), bool(smooth),
                    _opt(out_dir) or "", bool(quiet))
    res = SlamResult(path=r["path"], landmarks=Landmarks.from_entries(r["map"]),
                     stats=_json.loads(r["stats_json"]),
                     errors=_json_or_none(r["errors_json"]), error_table=r["error_table"])
    if smooth:
        res.smoothed_path = r["smoothed_path"]
        res.smoothed_landmarks = Landmarks.from_entries(r["smoothed_map"])
        res.smoothed_errors = _json_or_none(r["smoothed_errors_json"])
    return res


def localize(log, config=None, seed=1, emitters=None, gt_path=None, sets=(),
             odometry_only=False, out_dir=None, quiet=True):
    """rfir-localize (IR Monte Carlo localization) on a rawlog, in-process.
    `config`: an INI file or a stock INI by name (default: ir_localize)."""
    r = _rfir._localize(_os.fspath(log), _config_path(config, "ir_localize"), int(seed),
                        _opt(emitters) or "", _opt(gt_path) or "", list(sets),
                        bool(odometry_only), _opt(out_dir) or "", bool(quiet))
    return LocalizeResult(path=r["path"], odometry=r["odometry"],
                          stats=_json.loads(r["stats_json"]),
                          errors=_json_or_none(r["errors_json"]),
                          error_table=r["error_table"])


def evaluate(path, gt_path, map=None, gt_map=None, rawlog=None, label="estimate", kind=None,
             at_gt_times=False, no_odometry=False, segments=0, start=None):
    """rfir-eval: the errors of a path (a TUM file, an n x 4 array or a
    SlamResult/LocalizeResult) and of a map (a file, a Landmarks or, with a
    SlamResult, its landmarks) against the ground truth. Returns the JSON
    object rfir-eval prints."""
    with _tempfile.TemporaryDirectory(prefix="rfir-eval-") as tmp:
        if isinstance(path, SlamResult) and map is None:
            map = path.landmarks
        if isinstance(path, (SlamResult, LocalizeResult)):
            path = path.path
        if path is not None and not isinstance(path, (str, _os.PathLike)):
            save_tum(_np.asarray(path, dtype=float), _os.path.join(tmp, "path.tum"))
            path = _os.path.join(tmp, "path.tum")
        if isinstance(map, Landmarks):
            save_map(map, _os.path.join(tmp, "map.txt"))
            map = _os.path.join(tmp, "map.txt")
        if map is not None and gt_map is None:
            raise UsageError("map needs gt_map (the ground-truth map)")
        out = _os.path.join(tmp, "errors.json")
        _rfir._evaluate(_opt(path) or "", _os.fspath(gt_path) if gt_path else "",
                        _opt(map) or "", _opt(gt_map) or "", _opt(rawlog) or "", label,
                        kind or "", bool(at_gt_times), bool(no_odometry), int(segments),
                        None if start is None else [float(v) for v in start], out)
        with open(out) as f:
            return _json.load(f)


def load_map(file):
    """A map or ground-truth file (tag/landmark/emitter records) as Landmarks."""
    return Landmarks.from_entries(_rfir._load_map(_os.fspath(file)))


def save_map(landmarks, file, comment=""):
    """Writes Landmarks (or a list of entry dicts) as map.txt's records."""
    entries = landmarks.entries if isinstance(landmarks, Landmarks) else list(landmarks)
    _rfir._save_map(entries, _os.fspath(file), comment)


@_dataclass
class TextLog:
    """A text log (textlog 1) read whole: its header records as text and its
    timed records as dicts (kind, t, line, and the fields of the kind)."""
    header: str
    records: list


def read_textlog(file):
    """Reads and checks a whole text log (errors name FILE:LINE)."""
    header, records = _rfir._read_textlog(_os.fspath(file))
    return TextLog(header=header, records=records)
