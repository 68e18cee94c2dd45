#!/usr/bin/env python3
"""Every key a scenario file or a gear-set spec accepts is documented.

Reads the YAML parsers' sources (input/scenario_*.cpp, input/gearset_file.cpp), takes every key
they read by a literal name (the YamlMap accessors, the helpers that wrap them, the angle readers
whose `base` stands for `base_deg` and `base_rad`, key lists and the keys named in refusals), and
every value of a `choice` list. Each must appear as an inline code span, `key` (or a dotted path
ending in it, `solver.time_step_s`), in docs/scenario-reference.md or in one of the pages it links
for a section (solver.md, fe-reference.md, stiffness-tables.md, cad-gears.md). Fenced code blocks
do not count.

Exit 0 when every key and value is found; 1 naming each missing one and the source it came from,
or when fewer than MIN_KEYS keys were extracted or a pattern found none (a broken pattern must not
pass unnoticed).
Standard library only. Usage: check_scenario_keys.py [REPO_ROOT]
"""

import re
import sys
from pathlib import Path

SOURCES = [
    "input/scenario_file.cpp",
    "input/scenario_settings.cpp",
    "input/scenario_shapes.cpp",
    "input/scenario_pair.cpp",
    "input/scenario_planetary.cpp",
    "input/scenario_planetary_members.cpp",
    "input/scenario_stages.cpp",
    "input/scenario_stiffness.cpp",
    "input/scenario_sensors.cpp",
    "input/scenario_events.cpp",
    "input/scenario_fe.cpp",
    "input/scenario_macros.cpp",
    "input/gearset_file.cpp",
]
DOCS = [
    "docs/scenario-reference.md",
    "docs/solver.md",
    "docs/fe-reference.md",
    "docs/stiffness-tables.md",
    "docs/cad-gears.md",
]
# The parsers read well over 150 keys; fewer than this means a pattern no longer matches.
MIN_KEYS = 100

KEY = r'"([a-z][A-Za-z0-9_]*)"'
# YamlMap's accessors (input/yaml_reader.hpp), called on a map: m.number("key", …).
METHODS = (r"has|has_map|number|number_or|optional_number|integer|integer_or|numbers|strings|string|"
           r"string_or|boolean_or|choice|choice_or|map|list_of_maps|location")
# Helpers whose first argument is the map and second the key: number_within(m, "key", …).
MAP_HELPERS = (r"given|positive|vec3_or|vec3_within_or|number_within|number_within_or|integer_within|"
               r"integer_within_or|joint_ref|named_gear|named|shape_member|member_involutes|"
               r"require_safe_name|require_label")
# Helpers (lambdas) of one map whose first argument is the key: num("module_m", …).
KEY_HELPERS = r"num|multibody_only|part_of|body"
# Angle readers: angle_rad_or(m, "base", …) and the gear's angle("base", …) read base_deg or base_rad.
ANGLE_MAP_HELPERS = r"angle_rad_or"
ANGLE_KEY_HELPERS = r"angle"

PATTERNS = [
    (re.compile(r"\.(?:" + METHODS + r")\(\s*" + KEY), False),
    (re.compile(r"\b(?:" + MAP_HELPERS + r")\(\s*[\w*.>-]+\s*,\s*" + KEY), False),
    (re.compile(r"\b(?:" + KEY_HELPERS + r")\(\s*" + KEY), False),
    (re.compile(r"\b(?:" + ANGLE_MAP_HELPERS + r")\(\s*[\w*.>-]+\s*,\s*" + KEY), True),
    (re.compile(r"\b(?:" + ANGLE_KEY_HELPERS + r")\(\s*" + KEY), True),
]
# A refusal names its key in its first argument: m.fail("key", …), m.fail(m.has("a") ? "a" : "b", …).
FAIL = re.compile(r"\bfail\(")
# for (const char* key : {"a", "b"}): keys read or refused in a loop.
KEY_LIST = re.compile(r"for\s*\(\s*const\s+char\s*\*\s*\w+\s*:\s*\{([^}]*)\}")
# m.choice("key", {"a", "b"}) and choice_or: the values a key allows.
CHOICE = re.compile(r"\.choice(?:_or)?\(\s*" + KEY + r"\s*,\s*\{([^}]*)\}")
LITERAL = re.compile(KEY)
# A C++ string or character literal (kept whole while comments are stripped and arguments split).
LITERAL_TOKEN = re.compile(r'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])+\'')


def strip_comments(text):
    """The C++ source without // and /* */ comments (string and character literals kept whole)."""
    token = re.compile(LITERAL_TOKEN.pattern + r"|//[^\n]*|/\*.*?\*/", re.S)
    return token.sub(lambda m: m.group(0) if m.group(0)[0] in "\"'" else " ", text)


def first_argument(text, start):
    """The text of a call's first argument, from just after its "(" to the "," or ")" ending it."""
    depth, i = 0, start
    while i < len(text):
        literal = LITERAL_TOKEN.match(text, i)
        if literal:
            i = literal.end()
            continue
        c = text[i]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            if depth == 0:
                break
            depth -= 1
        elif c == "," and depth == 0:
            break
        i += 1
    return text[start:i]


def extract(root):
    """{key: first source}, {(key, value): first source}, [rule that matched nothing]."""
    keys, values = {}, {}
    hits = {f"PATTERNS[{i}]": 0 for i in range(len(PATTERNS))}
    hits.update(FAIL=0, KEY_LIST=0, CHOICE=0)
    for rel in SOURCES:
        path = root / rel
        if not path.is_file():
            sys.exit(f"check_scenario_keys: parser source {rel} not found")
        text = strip_comments(path.read_text(encoding="utf-8"))
        found = []
        for i, (pattern, angle) in enumerate(PATTERNS):
            for m in pattern.finditer(text):
                hits[f"PATTERNS[{i}]"] += 1
                found += [m.group(1) + "_deg", m.group(1) + "_rad"] if angle else [m.group(1)]
        for m in FAIL.finditer(text):
            named = LITERAL.findall(first_argument(text, m.end()))
            hits["FAIL"] += len(named)
            found += named
        for m in KEY_LIST.finditer(text):
            hits["KEY_LIST"] += 1
            found += LITERAL.findall(m.group(1))
        for m in CHOICE.finditer(text):
            hits["CHOICE"] += 1
            for value in re.findall(r'"([^"]+)"', m.group(2)):
                values.setdefault((m.group(1), value), rel)
        for name in found:
            keys.setdefault(name, rel)
    return keys, values, [rule for rule, n in hits.items() if n == 0]


def code_spans(root):
    """The content of every inline code span of the docs, whitespace collapsed."""
    spans = set()
    for rel in DOCS:
        path = root / rel
        if not path.is_file():
            sys.exit(f"check_scenario_keys: doc {rel} not found")
        text = re.sub(r"^```.*?^```", "", path.read_text(encoding="utf-8"), flags=re.S | re.M)
        for m in re.finditer(r"`([^`]+)`", text):
            spans.add(" ".join(m.group(1).split()))
    return spans


def documented(name, spans, key=None):
    """`name` as a span, a dotted path ending in it (`solver.name`, `joints[].name`) or, for a
    value of `key`, `key: name`."""
    tail = re.compile(r"^(?:[\w\[\]]+\.)*" + re.escape(name) + "$")
    return any(tail.match(s) for s in spans) or (key is not None and f"{key}: {name}" in spans)


def main():
    root = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent
    keys, values, idle = extract(root)
    spans = code_spans(root)
    if len(keys) < MIN_KEYS or idle:
        print(f"check_scenario_keys: {len(keys)} keys found in the parsers (expected at least {MIN_KEYS})"
              + (f"; no match for {', '.join(idle)}" if idle else "")
              + ": the extraction patterns no longer match the sources")
        return 1
    missing = [(src, f"key `{k}`") for k, src in sorted(keys.items()) if not documented(k, spans)]
    missing += [(src, f"value `{v}` of `{k}`") for (k, v), src in sorted(values.items()) if not documented(v, spans, key=k)]
    for src, what in missing:
        print(f"{src}: {what} is not documented")
    if missing:
        print("check_scenario_keys: document each as `name` in " + ", ".join(DOCS))
    print(f"check_scenario_keys: {len(keys)} keys and {len(values)} choice values checked, {len(missing)} undocumented")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
