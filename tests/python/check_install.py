"""The installed module (downstream_package): imported from the prefix, it
reads the prefix's stock INIs and its SLAM path is the installed rfir-slam's.
    check_install.py PREFIX RAWLOG PROGRAM_PATH_TUM OUT_TUM"""
import os
import sys

import rfir

prefix, rawlog, program_tum, out_tum = sys.argv[1:5]
prefix = os.path.realpath(prefix)
for what, path in (("the package", rfir.__file__), ("the stock INIs", rfir.stock_config_dir())):
    if not os.path.realpath(path).startswith(prefix + os.sep):
        sys.exit("%s: %s, not in %s" % (what, path, prefix))
res = rfir.slam(rawlog, method="ps", seed=1)
rfir.save_tum(res.path, out_tum)
with open(program_tum, "rb") as a, open(out_tum, "rb") as b:
    if a.read() != b.read():
        sys.exit("rfir.slam's path differs from the installed rfir-slam's " + program_tum)
print("rfir %s from %s: %d poses, the installed rfir-slam's path.tum"
      % (rfir.__version__, os.path.dirname(rfir.__file__), len(res.path)))
