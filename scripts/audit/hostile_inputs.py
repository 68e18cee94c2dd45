#!/usr/bin/env python3
"""Hostile-input audit of the gearsim CLI and Python module: many kinds of bad, recursive,
oversized, linked and concurrent input, and failing disks, each run and classified.

Each case ends as one of
  ok       a clean refusal (exit 2, 6, 7, a Python exception) or a correct result;
  crash    a signal, exit 3 (internal error) or another code gearsim does not define;
  hang     no end within the case's time limit (killed);
  escape   a file outside the case's output folder was created, changed or removed;
  broken   exit 0 with an output cut short (a CSV row, JSON, HDF5 that is not whole) or a
           status other than "completed" in summary.json; from Python, a result for input the
           CLI refuses.
Prints the totals per family and per class; exits 1 when any case is not ok.

Usage: scripts/audit/hostile_inputs.py [--gearsim build/bin/gearsim] [--python-path build/python]
                                       [--work DIR] [--quick]
  --quick: a few cases of each family (about a minute), as ctest runs it.
"""
import argparse
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

import yaml

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import audit_cases  # noqa: E402  (the case families)

KNOWN_CODES = {0, 2, 4, 5, 6, 7, 8, 130, 143}


def snapshot(folder):
    """{relative path: (size, mtime_ns)} of every entry below folder, links not followed."""
    out = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            p = pathlib.Path(root) / name
            st = p.lstat()
            out[str(p.relative_to(folder))] = (st.st_size, st.st_mtime_ns)
    return out


def broken_outputs(folder, unchanged=None):
    """What is cut short among the outputs below folder ('' when all are whole); files in
    `unchanged` ({relative path: (size, mtime)} as snapshot() gives, the case's own inputs left as
    they were) are not outputs of the command."""
    unchanged = unchanged or {}
    problems = []
    for root, _, files in os.walk(folder):
        for name in files:
            p = pathlib.Path(root) / name
            # Only regular files: a FIFO or device the case planted is not an output (and a FIFO
            # would block this read).
            if p.is_symlink() or not p.is_file() or name.startswith("."):
                continue
            st = p.lstat()
            if unchanged.get(str(p.relative_to(folder))) == (st.st_size, st.st_mtime_ns):
                continue
            data = p.read_bytes()
            if name.endswith(".csv"):
                lines = data.decode("utf-8", "replace").split("\n")
                width = lines[0].count(",")
                if not data.endswith(b"\n") or any(line.count(",") != width for line in lines[1:-1]):
                    problems.append(f"{name}: cut short")
            elif name.endswith(".json"):
                try:
                    json.loads(data)
                except ValueError:
                    problems.append(f"{name}: not whole JSON")
            elif name.endswith(".h5") and not data.startswith(b"\x89HDF\r\n\x1a\n"):
                problems.append(f"{name}: not HDF5")
    return "; ".join(problems)


def run_case(case, gearsim, work, victim):
    """Runs one case (audit_cases.Case) in its own folder; returns (class, detail)."""
    folder = work / case.name
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    before = snapshot(victim)
    env = dict(os.environ, **case.env)
    try:
        args = case.prepare(folder)
        inputs = snapshot(folder / "out") if (folder / "out").is_dir() else {}
        if case.python:
            cmd = [sys.executable, "-c", args]
        else:
            cmd = [str(gearsim), *map(str, args)]
        r = subprocess.run(cmd, cwd=folder, env=env, capture_output=True, timeout=case.timeout_s)
        code, output = r.returncode, (r.stdout + r.stderr).decode("utf-8", "replace")
    except subprocess.TimeoutExpired:
        return "hang", f"no end within {case.timeout_s} s"
    finally:
        case.cleanup(folder)
    if snapshot(victim) != before:
        return "escape", "the folder outside the output changed"
    if case.python:
        # The case's script prints AUDIT-REFUSED when the module refused as it should, and
        # AUDIT-ACCEPTED when it returned a result for input it should have refused.
        if code < 0:
            return "crash", f"the interpreter died (signal {-code}): {output[-300:]}"
        if "AUDIT-REFUSED" in output:
            return "ok", output[-200:]
        if "AUDIT-ACCEPTED" in output:
            return "broken", output[-300:]
        return "crash", f"exit {code}: {output[-300:]}"
    if code < 0 or code not in KNOWN_CODES or code == 3:
        return "crash", f"exit {code}: {output[-300:]}"
    if code == 0:
        out = folder / "out"
        if out.exists():
            problems = broken_outputs(out, inputs)
            summary = out / "summary.json"
            if not problems and summary.exists():
                status = json.loads(summary.read_text()).get("status")
                if status != "completed":
                    problems = f"exit 0 with status {status}"
            if problems:
                return "broken", problems
    return "ok", f"exit {code}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--gearsim", default=str(HERE.parents[1] / "build" / "bin" / "gearsim"))
    ap.add_argument("--work", default=None, help="scratch folder (default: a temporary one)")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--only", default="", help="only the cases whose family/name holds this text")
    ap.add_argument("--python-path", default=str(HERE.parents[1] / "build" / "python"),
                    help="the folder of the gearsim Python module")
    a = ap.parse_args()
    gearsim = pathlib.Path(a.gearsim).resolve()
    work = pathlib.Path(a.work or tempfile.mkdtemp(prefix="gearsim_audit_")).resolve()
    work.mkdir(parents=True, exist_ok=True)
    victim = work / "victim"
    victim.mkdir(exist_ok=True)
    (victim / "precious.txt").write_text("the user's\n")
    (victim / "state.csv").write_text("the user's\n")
    cases = audit_cases.all_cases(gearsim, work, victim, quick=a.quick, python_path=a.python_path)
    cases = [c for c in cases if a.only in f"{c.family}/{c.name}"]
    totals, failures = {}, []
    for case in cases:
        cls, detail = run_case(case, gearsim, work / "cases", victim)
        fam = totals.setdefault(case.family, {})
        fam[cls] = fam.get(cls, 0) + 1
        if cls != "ok":
            failures.append((case.family, case.name, cls, detail))
    classes = ["ok", "crash", "hang", "escape", "broken"]
    print(f"{'family':28s} " + " ".join(f"{c:>7s}" for c in classes))
    for fam, counts in totals.items():
        print(f"{fam:28s} " + " ".join(f"{counts.get(c, 0):7d}" for c in classes))
    grand = {c: sum(t.get(c, 0) for t in totals.values()) for c in classes}
    print(f"{'total (' + str(len(cases)) + ' cases)':28s} " + " ".join(f"{grand[c]:7d}" for c in classes))
    for fam, name, cls, detail in failures:
        print(f"{cls}: {fam}/{name}: {detail}")
    if not a.work:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
