"""The case families of the hostile-input audit (hostile_inputs.py): each case prepares its
folder, gives the command line (or a Python script) to run there, and cleans up what it made."""
import copy
import os
import pathlib
import shutil
import subprocess

import yaml

SOURCE = pathlib.Path(__file__).resolve().parents[2]
SCENARIOS = SOURCE / "assets" / "scenarios"
SPECS = SOURCE / "assets" / "specs"
# Values a scalar of a scenario or spec is replaced with: out of range, not finite, not a number,
# a collection where a scalar belongs, a recursive alias.
MUTATIONS = ["1.0e300", "-1", "0", ".nan", ".inf", "-.inf", "abc", "[1, 2]", "{a: 1}", "&r [1, *r]", "''"]
RECORD_KINDS = ["fifo", "dev_zero", "folder", "link_loop", "empty", "garbage", "truncated"]


class Case:
    def __init__(self, family, name, prepare, python=False, env=None, timeout_s=120, cleanup=None):
        self.family, self.name, self.python = family, name, python
        self.prepare, self.env, self.timeout_s = prepare, env or {}, timeout_s
        self.cleanup = cleanup or (lambda folder: None)


def scalar_paths(node, path=()):
    """Every scalar leaf of a YAML tree as a key path (tuple of keys and list indices)."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield from scalar_paths(v, path + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from scalar_paths(v, path + (i,))
    else:
        yield path


def with_value(tree, path, text):
    """A copy of the YAML text of tree whose leaf at path is the YAML `text` (kept verbatim)."""
    t = copy.deepcopy(tree)
    node = t
    for k in path[:-1]:
        node = node[k]
    node[path[-1]] = "@@VALUE@@"
    return yaml.safe_dump(t, sort_keys=False).replace("'@@VALUE@@'", text)


def absolute_paths(tree, base):
    """The scenario's relative file names made absolute (the copy is loaded from elsewhere)."""
    if isinstance(tree, dict):
        return {k: absolute_paths(v, base) for k, v in tree.items()}
    if isinstance(tree, list):
        return [absolute_paths(v, base) for v in tree]
    if isinstance(tree, str) and tree.startswith("../"):
        return str((base / tree).resolve())
    return tree


def make_kind(path, kind, victim):
    """Puts a file of `kind` at path (replacing what is there)."""
    if path.is_symlink() or path.is_file():
        path.unlink()
    elif path.is_dir():
        shutil.rmtree(path)
    text = None
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "dev_zero":
        path.symlink_to("/dev/zero")
    elif kind == "folder":
        path.mkdir()
    elif kind == "link_loop":
        path.symlink_to(path.name)
    elif kind == "victim_link":
        path.symlink_to(victim / "precious.txt")
    elif kind == "empty":
        text = ""
    elif kind == "garbage":
        text = "\x00\xff{[\n" * 100
    if text is not None:
        path.write_text(text, errors="surrogateescape")


def value_cases(family, tree, file_name, command, quick):
    """Every scalar leaf of `tree` replaced by each of MUTATIONS, written as file_name and run."""
    paths = list(scalar_paths(tree))
    for i, path in enumerate(paths[:4] if quick else paths):
        for m in MUTATIONS[:3] if quick else MUTATIONS:
            text = with_value(tree, path, m)

            def prepare(folder, text=text):
                (folder / file_name).write_text(text)
                return command
            yield Case(family, f"leaf{i}_{MUTATIONS.index(m)}", prepare)


def scenario_value_cases(gearsim, quick):
    tree = absolute_paths(yaml.safe_load((SCENARIOS / "spur_pair.yaml").read_text()), SCENARIOS)
    tree["duration_s"] = 0.06
    return value_cases("scenario values", tree, "s.yaml", ["run", "s.yaml", "--out", "out", "--no-analyze"], quick)


def spec_value_cases(gearsim, quick):
    tree = yaml.safe_load((SPECS / "spur_pair_gearset.yaml").read_text())
    return value_cases("gear-set spec values", tree, "spec.yaml", ["gears", "spec.yaml", "--out", "out"], quick)


def recursion_cases(gearsim, base_run, quick):
    rec = "duration_s: 0.1\nx: &r [1, *r]\n"
    bomb = "x0: &x0 [1, 1, 1, 1, 1, 1, 1, 1, 1]\n" + "".join(
        f"x{k}: &x{k} [" + ", ".join([f"*x{k - 1}"] * 9) + "]\n" for k in range(1, 10))
    def file_case(name, text, cmd):
        def prepare(folder):
            (folder / "f.yaml").write_text(text)
            return cmd
        return Case("recursion and alias bombs", name, prepare)
    yield file_case("run", rec, ["run", "f.yaml", "--out", "out"])
    yield file_case("gears", rec, ["gears", "f.yaml"])
    yield file_case("sweep", "name: s\nscenario: f.yaml\n" + rec, ["sweep", "f.yaml", "--out", "out"])
    yield file_case("bomb", "duration_s: 0.1\n" + bomb, ["run", "f.yaml", "--out", "out"])
    spur = str(SCENARIOS / "spur_pair.yaml")
    yield file_case("set", "", ["run", spur, "--out", "out", "--set", "x=&r [1, *r]"])
    yield file_case("set_bomb", "", ["run", spur, "--out", "out", "--set",
                                     "x={" + bomb.replace("\n", ", ").rstrip(", ") + "}"])

    def gearset_in_run(folder):
        shutil.copytree(base_run, folder / "out", symlinks=True)
        (folder / "out" / "gearset.yaml").write_text(rec)
        return ["report", "out"]
    yield Case("recursion and alias bombs", "run_folder_gearset", gearset_in_run)


def file_kind_cases(gearsim, base_run, victim, quick):
    spur = SCENARIOS / "spur_pair.yaml"
    for kind in RECORD_KINDS:
        def scenario(folder, kind=kind):
            make_kind(folder / "s.yaml", kind, victim)
            return ["run", "s.yaml", "--out", "out"]
        yield Case("file kinds: scenario", kind, scenario, timeout_s=60)

        def mesh(folder, kind=kind):
            text = spur.read_text().replace("../gears/spur_pair/pinion.stl", str(folder / "m.stl"))
            (folder / "s.yaml").write_text(text.replace("../", str(SOURCE / "assets") + "/"))
            make_kind(folder / "m.stl", kind, victim)
            return ["run", "s.yaml", "--out", "out", "--duration", "0.06"]
        yield Case("file kinds: mesh", kind, mesh, timeout_s=60)
    records = ["summary.json", "scenario.json", "state.csv", "contacts.csv", "steps.h5", "analysis.json"]
    for record in records[:2] if quick else records:
        for kind in RECORD_KINDS[:3] if quick else RECORD_KINDS + ["victim_link"]:
            for cmd in (["analyze", "out"], ["report", "out"], ["render", "out", "--width", "64", "--height", "64"]):
                def run_record(folder, record=record, kind=kind, cmd=cmd):
                    shutil.copytree(base_run, folder / "out", symlinks=True)
                    p = folder / "out" / record
                    if kind == "truncated":
                        p.write_bytes(p.read_bytes()[: p.stat().st_size // 2])
                    else:
                        make_kind(p, kind, victim)
                    return cmd
                yield Case("file kinds: run records", f"{record}_{kind}_{cmd[0]}", run_record, timeout_s=60)


def summary_value_cases(gearsim, base_run, quick):
    summary = (base_run / "summary.json").read_text()
    tree = yaml.safe_load(summary)
    keys = [p for p in scalar_paths(tree) if len(p) <= 3]
    for i, path in enumerate(keys[:5] if quick else keys):
        for m in ['"abc"', "-1", "1e308", "null"]:
            def prepare(folder, path=path, m=m):
                shutil.copytree(base_run, folder / "out", symlinks=True)
                t = copy.deepcopy(tree)
                node = t
                for k in path[:-1]:
                    node = node[k]
                node[path[-1]] = "@@V@@"
                (folder / "out" / "summary.json").write_text(
                    __import__("json").dumps(t).replace('"@@V@@"', m))
                return ["report", "out"]
            yield Case("run record values", f"{'.'.join(map(str, path))}={m}", prepare, timeout_s=60)


def planted_link_cases(gearsim, victim, quick):
    spur = str(SCENARIOS / "spur_pair.yaml")
    names = ["state.csv", "contacts.csv", "steps.h5", "summary.json", "scenario.json", "analysis.json",
             "spectrum.csv", "report.html", ".gearsim-manifest", ".gearsim.lock", "frames"]
    for n in names[:3] if quick else names:
        def prepare(folder, n=n):
            (folder / "out").mkdir()
            (folder / "out" / n).symlink_to(victim / "precious.txt" if n != "frames" else victim)
            return ["run", spur, "--out", "out", "--duration", "0.3", "--force"]
        yield Case("planted links", n, prepare)

    def linked_out(folder):
        (folder / "out").symlink_to(victim)
        return ["run", spur, "--out", "out", "--duration", "0.06"]
    yield Case("planted links", "out_is_a_link", linked_out)
    sweep = ("name: s\nscenario: " + spur + "\nset: [\"duration_s=0.15\", \"output.per_step_log=false\"]\n"
             "cases:\n  - loads[0].constant_torque_N_m: 5\n  - loads[0].constant_torque_N_m: 6\n")
    for what in ["run.out.log", "run.err.log", "case_folder", "case_file", "cases"]:
        def prepare(folder, what=what):
            (folder / "s.yaml").write_text(sweep)
            case = folder / "out" / "cases" / "00000"
            if what == "cases":
                (folder / "out").mkdir()
                (folder / "out" / "cases").symlink_to(victim)
            else:
                case.parent.mkdir(parents=True)
                if what == "case_folder":
                    case.symlink_to(victim)
                elif what == "case_file":
                    case.write_text("x\n")
                else:
                    case.mkdir()
                    (case / what).symlink_to(victim / "precious.txt")
            return ["sweep", "s.yaml", "--out", "out", "--jobs", "1"]
        yield Case("planted links: sweep", what, prepare)


def python_cases(python_path):
    head = ("import gearsim, math, sys\n"
            f"s = gearsim.load_scenario({str(SCENARIOS / 'spur_pair.yaml')!r}, {{'output.per_step_log': False}})\n")
    calls = {"run_duration_1e9": "gearsim.run(s, duration=1e9)", "run_duration_inf": "gearsim.run(s, duration=math.inf)",
             "run_duration_nan": "gearsim.run(s, duration=math.nan)", "run_duration_neg": "gearsim.run(s, duration=-1)",
             "modes_harmonics_neg": "gearsim.modes(s, harmonics=-1)", "modes_phases_0": "gearsim.modes(s, phases=0)",
             "analyze_missing": "gearsim.analyze('no_such_folder')",
             "load_recursive": "open('r.yaml','w').write('duration_s: 0.1\\nx: &r [1, *r]\\n'); gearsim.load_scenario('r.yaml')",
             "set_recursive": f"gearsim.load_scenario({str(SCENARIOS / 'spur_pair.yaml')!r}, {{'x': '&r [1, *r]'}})"}
    for name, call in calls.items():
        script = head + ("try:\n    " + call + "\n    print('AUDIT-ACCEPTED')\n"
                         "except (ValueError, OSError, TypeError) as e:\n    print('AUDIT-REFUSED', e)\n")
        yield Case("python module", name, lambda folder, script=script: script, python=True, timeout_s=60,
                   env={"PYTHONPATH": str(python_path)})


def full_disk_cases(gearsim, base_run, quick):
    if os.geteuid() != 0:
        return
    spur = str(SCENARIOS / "spur_pair.yaml")
    for size in ["8k", "64k", "256k", "2m"][: 2 if quick else 4]:
        for cmd in ("run", "analyze", "sweep"):
            def prepare(folder, size=size, cmd=cmd):
                disk = folder / "disk"
                disk.mkdir()
                if cmd != "analyze":
                    subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(disk)], check=True)
                    if cmd == "sweep":
                        (folder / "s.yaml").write_text("name: s\nscenario: " + spur + "\nset: [\"duration_s=0.15\"]\n"
                                                       "cases:\n  - loads[0].constant_torque_N_m: 5\n")
                        return ["sweep", "s.yaml", "--out", "disk/out", "--jobs", "1"]
                    return ["run", spur, "--out", "disk/out", "--duration", "0.5"]
                # A finished run on a disk then filled, with `size` left free.
                subprocess.run(["mount", "-t", "tmpfs", "-o", "size=16m", "tmpfs", str(disk)], check=True)
                shutil.copytree(base_run, disk / "out", symlinks=True)
                fd = os.open(disk / "fill", os.O_WRONLY | os.O_CREAT)
                try:
                    while True:
                        os.write(fd, b"\0" * 4096)
                except OSError:
                    os.close(fd)
                os.truncate(disk / "fill", max(0, (disk / "fill").stat().st_size - parse_size(size)))
                return ["analyze", "disk/out"]

            def cleanup(folder):
                subprocess.run(["umount", str(folder / "disk")], check=False)
            yield Case("full disk", f"{cmd}_{size}", prepare, cleanup=cleanup)


def parse_size(text):
    return int(text[:-1]) * {"k": 1 << 10, "m": 1 << 20}[text[-1]]


def all_cases(gearsim, work, victim, quick=False, python_path=SOURCE / "build" / "python"):
    base_run = work / "base_run"
    if not (base_run / "analysis.json").exists():
        shutil.rmtree(base_run, ignore_errors=True)
        subprocess.run([str(gearsim), "run", str(SCENARIOS / "spur_pair.yaml"), "--out", str(base_run), "--duration", "0.3"],
                       check=True, capture_output=True)
    cases = []
    cases += recursion_cases(gearsim, base_run, quick)
    cases += file_kind_cases(gearsim, base_run, victim, quick)
    cases += planted_link_cases(gearsim, victim, quick)
    cases += python_cases(python_path)
    cases += full_disk_cases(gearsim, base_run, quick)
    cases += summary_value_cases(gearsim, base_run, quick)
    cases += spec_value_cases(gearsim, quick)
    cases += scenario_value_cases(gearsim, quick)
    return cases
