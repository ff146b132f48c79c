#!/usr/bin/env python3
"""Rewrite a parameter file of vesicle-iga 0.x (before the one engine) in the
names of the current version, keeping comments and values:

  willmore-flow: End time, Max steps, rho_inf, VTU interval, Checkpoint
    interval, Restart from and the stationarity entries move into
    subsection "Time stepping"; the entries of subsection "Time step" too,
    with "Adaptive = false" becoming "Step control = fixed"; "Max Newton
    iterations", "Newton relative/absolute tolerance" become subsection
    "Newton"; "Linear solver benchmark" is dropped (tools/bench).
  navier-stokes: in "Time stepping", "Time step" -> "Initial dt",
    "Max time step" -> "Max dt", "Time step growth" -> "Growth factor" (with
    "Step control = growing" when it is not 1), "Pressure time level" ->
    "Algebraic fields at".

Usage: tools/upgrade-prm.py FILE.prm [FILE.prm ...]   (rewrites in place)
       tools/upgrade-prm.py - < old.prm > new.prm
Files already in the new form are left unchanged.
"""
import re
import sys


class Node:
    """A subsection: entries and subsections in order, with comments."""

    def __init__(self, name, indent=""):
        self.name = name
        self.indent = indent
        self.items = []  # ("set", name, value, comments, raw) | ("sub", Node, comments)
        self.trailing = []  # comments before "end"


def parse(lines):
    root = Node(None)
    stack = [root]
    pending = []
    for raw in lines:
        line = raw.rstrip("\n")
        s = line.strip()
        if s == "" or s.startswith("#"):
            pending.append(line)
            continue
        m = re.match(r"(\s*)subsection\s+(.*?)\s*$", line)
        if m:
            node = Node(m.group(2), m.group(1))
            stack[-1].items.append(("sub", node, pending))
            pending = []
            stack.append(node)
            continue
        if re.match(r"\s*end\s*$", line):
            stack[-1].trailing = pending
            pending = []
            stack.pop()
            continue
        m = re.match(r"(\s*)set\s+(.*?)\s*=\s*(.*?)\s*$", line)
        if m:
            stack[-1].items.append(("set", m.group(2), m.group(3), pending, m.group(1)))
            pending = []
            continue
        pending.append(line)  # unknown line: keep it verbatim
    root.trailing = pending
    return root


def emit(node, depth, out):
    pad = "  " * depth
    for item in node.items:
        if item[0] == "set":
            _, name, value, comments, _ = item
            out.extend(comments)
            out.append(f"{pad}set {name} = {value}")
        else:
            _, sub, comments = item
            out.extend(comments)
            out.append(f"{pad}subsection {sub.name}")
            emit(sub, depth + 1, out)
            out.extend(sub.trailing)
            out.append(f"{pad}end")


def find_sub(node, name, create=False):
    for item in node.items:
        if item[0] == "sub" and item[1].name == name:
            return item[1]
    if not create:
        return None
    sub = Node(name)
    node.items.append(("sub", sub, []))
    return sub


def take(node, name):
    for i, item in enumerate(node.items):
        if item[0] == "set" and item[1] == name:
            return node.items.pop(i)
    return None


def put(node, item, new_name=None, new_value=None):
    _, name, value, comments, indent = item
    node.items.append(("set", new_name or name, new_value if new_value is not None else value, comments, indent))


def upgrade_willmore(section):
    stepping = find_sub(section, "Time stepping", create=False)
    old_step = find_sub(section, "Time step")
    moves = ["End time", "Max steps", "rho_inf", "VTU interval",
             "Checkpoint interval", "Restart from", "Stationarity tolerance",
             "Stationarity measure", "Stationary interface speed"]
    if stepping is None and (old_step is not None or any(
            it[0] == "set" and it[1] in moves for it in section.items)):
        stepping = find_sub(section, "Time stepping", create=True)
    for name in moves:
        item = take(section, name)
        if item:
            put(stepping, item)
    if old_step is not None:
        section.items = [it for it in section.items
                         if not (it[0] == "sub" and it[1] is old_step)]
        for item in old_step.items:
            if item[0] != "set":
                continue
            if item[1] == "Adaptive":
                adaptive = item[2].lower() in ("true", "1", "yes")
                put(stepping, item, "Step control",
                    "adaptive" if adaptive else "fixed")
            else:
                put(stepping, item)
    newton_names = {"Max Newton iterations": "Max iterations",
                    "Newton relative tolerance": "Relative tolerance",
                    "Newton absolute tolerance": "Absolute tolerance"}
    for old, new in newton_names.items():
        item = take(section, old)
        if item:
            put(find_sub(section, "Newton", create=True), item, new)
    take(section, "Linear solver benchmark")


def upgrade_flow(section):
    stepping = find_sub(section, "Time stepping")
    if stepping is None:
        return
    renames = {"Time step": "Initial dt", "Max time step": "Max dt",
               "Pressure time level": "Algebraic fields at"}
    for old, new in renames.items():
        item = take(stepping, old)
        if item:
            put(stepping, item, new)
    item = take(stepping, "Time step growth")
    if item:
        put(stepping, item, "Growth factor")
        if float(item[2]) != 1 and not any(
                it[0] == "set" and it[1] == "Step control" for it in stepping.items):
            stepping.items.append(("set", "Step control", "growing", [], ""))


def upgrade(text):
    root = parse(text.splitlines())
    before = []
    emit(root, 0, before)
    for name, fn in (("Willmore flow", upgrade_willmore),
                     ("Navier-Stokes", upgrade_flow)):
        section = find_sub(root, name)
        if section is not None:
            fn(section)
    out = []
    emit(root, 0, out)
    if out == before:
        return text  # nothing to upgrade: keep the file as it is
    out.extend(root.trailing)
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) == 2 and sys.argv[1] == "-":
        sys.stdout.write(upgrade(sys.stdin.read()))
        return
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for path in sys.argv[1:]:
        with open(path) as f:
            old = f.read()
        new = upgrade(old)
        if new != old:
            with open(path, "w") as f:
                f.write(new)
            print(f"upgraded {path}")


if __name__ == "__main__":
    main()
