"""Runs the ```python blocks of a docs page, in order, as one script (ctest
python_docs_example), so that the page's example cannot rot; then checks
what docs/python.md's example says it makes.
    run_docs_example.py PAGE SOURCE_DIR WORK_DIR   (MPLBACKEND=Agg)"""
import os
import re
import shutil
import sys

import rfir

page, src, work = sys.argv[1:4]
with open(page) as f:
    blocks = re.findall(r"^```python\n(.*?)^```", f.read(), re.S | re.M)
if not blocks:
    sys.exit("%s: no ```python block" % page)
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
os.symlink(os.path.join(src, "datasets"), os.path.join(work, "datasets"))
os.chdir(work)  # the page's paths are relative to the source folder
code = "\n".join(blocks)
exec(compile(code, page, "exec"), {"__name__": "__main__"})

# The CSV's conversion is the bundled text log's: the same rawlog.
rfir.import_textlog("datasets/tutorial_robot.txt", "reference.rawlog")
with open("reference.rawlog", "rb") as a, open("out/python/robot.rawlog", "rb") as b:
    assert a.read() == b.read(), "the CSV conversion differs from tutorial_robot.txt"
assert os.path.getsize("out/python/path_map.png") > 0
print("%s: %d code blocks ran" % (page, len(blocks)))
