#!/usr/bin/env python3
"""Fuzz the parameter handling of vesicle-iga.

Mutates parameter files (numbers to 0, negative, huge, nan, inf, text;
lists shortened and lengthened; lines dropped, duplicated, misspelt;
subsections unbalanced; binary junk; truncation) and runs
`vesicle-iga --check` on every mutant and, with --run, a few steps of the
mutants that --check accepts (for studies whose unmutated file takes at most
--cheap seconds for those steps). Every outcome is classified:

  accepted      exit 0
  refused       exit 1 with one "vesicle-iga: error:" message
  CRASH         a signal, an abort, an uncaught exception, another exit code
  HANG          the time limit was reached
  INVALID       a non-finite number (nan, inf) was accepted

Usage: tools/fuzz-prm.py [--cases N] [--seed S] [--run] [--timeout T]
                         [--jobs J] [--binary build/vesicle-iga] [FILE.prm ...]
Default files: prm/*.prm. Prints a summary and each finding; exit code 1 if
any CRASH, HANG or INVALID was found.
"""
import argparse
import concurrent.futures
import glob
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

NUMBER = re.compile(r"(?<![\w.])[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?(?![\w.])")
REPLACEMENTS = ["0", "-1", "-0.5", "1e300", "-1e300", "99999999999", "nan",
                "inf", "-inf", "abc", "", "1e-300", "2147483648"]
NON_FINITE = {"nan", "inf", "-inf"}


def mutate(lines, rng):
    """One random mutation; returns (new lines, description, non_finite)."""
    lines = list(lines)
    settings = [i for i, l in enumerate(lines) if l.strip().startswith("set ")]
    kind = rng.choice(["number"] * 6 + ["list-short", "list-long", "drop",
                                        "duplicate", "misspell", "unbalance",
                                        "junk", "truncate"])
    if kind == "number" and settings:
        # Numbers inside names (directories, files) are not values.
        candidates = [i for i in settings
                      if NUMBER.search(lines[i].split("=", 1)[-1])
                      and not re.search(r"directory|Restart from|Name",
                                        lines[i].split("=", 1)[0])]
        if candidates:
            i = rng.choice(candidates)
            name, value = lines[i].split("=", 1)
            matches = list(NUMBER.finditer(value))
            m = rng.choice(matches)
            new = rng.choice(REPLACEMENTS)
            lines[i] = name + "=" + value[:m.start()] + new + value[m.end():]
            return lines, f"{name.strip()} {m.group(0)} -> '{new}'", new in NON_FINITE
    if kind in ("list-short", "list-long") and settings:
        candidates = [i for i in settings if "," in lines[i].split("=", 1)[-1]]
        if candidates:
            i = rng.choice(candidates)
            name, value = lines[i].split("=", 1)
            parts = value.split(",")
            parts = parts[:-1] if kind == "list-short" else parts + [parts[-1]]
            lines[i] = name + "=" + ",".join(parts)
            return lines, f"{name.strip()} list {kind[5:]}", False
    if kind == "drop" and lines:
        i = rng.randrange(len(lines))
        return lines[:i] + lines[i + 1:], f"line {i + 1} dropped", False
    if kind == "duplicate" and lines:
        i = rng.randrange(len(lines))
        return lines[:i + 1] + [lines[i]] + lines[i + 1:], f"line {i + 1} twice", False
    if kind == "misspell" and settings:
        i = rng.choice(settings)
        name, value = lines[i].split("=", 1)
        word = name.strip()[4:]
        if len(word) > 2:
            k = rng.randrange(len(word) - 1)
            word = word[:k] + word[k + 1] + word[k] + word[k + 2:]
        lines[i] = "set " + word + " =" + value
        return lines, f"misspelt '{word}'", False
    if kind == "unbalance":
        ends = [i for i, l in enumerate(lines) if l.strip() == "end"]
        if ends and rng.random() < 0.5:
            i = rng.choice(ends)
            return lines[:i] + lines[i + 1:], f"'end' of line {i + 1} dropped", False
        return lines + ["end"], "extra 'end'", False
    if kind == "junk":
        junk = "".join(chr(rng.randrange(1, 256)) for _ in range(rng.randrange(1, 40)))
        i = rng.randrange(len(lines) + 1)
        return lines[:i] + [junk] + lines[i:], f"binary junk at line {i + 1}", False
    # truncate
    text = "\n".join(lines)
    cut = rng.randrange(len(text) + 1)
    return text[:cut].split("\n"), f"truncated at byte {cut}", False


def classify(proc, timed_out):
    if timed_out:
        return "HANG"
    out = proc.stdout + proc.stderr
    if proc.returncode < 0 or proc.returncode > 128:
        return "CRASH"
    if re.search(r"uncaught|terminate called|Aborted|MPI_ABORT|Segmentation", out):
        return "CRASH"
    if proc.returncode == 0:
        return "accepted"
    if proc.returncode == 1 and out.count("vesicle-iga: error:") == 1:
        return "refused"
    return "CRASH"


def run(args, timeout, cwd):
    try:
        p = subprocess.run(args, capture_output=True, timeout=timeout, cwd=cwd,
                           errors="replace", text=True)
        return p, False
    except subprocess.TimeoutExpired as e:
        class P:
            returncode = -1
            stdout = e.stdout.decode(errors="replace") if e.stdout else ""
            stderr = e.stderr.decode(errors="replace") if e.stderr else ""
        return P(), True


def few_steps(text):
    """The file with at most 2 time steps (or 1 refinement level) and no VTU."""
    return text + ("\n" + "\n".join(
        f"subsection {s}\n subsection Time stepping\n  set Max steps = 2\n"
        f"  set VTU interval = 0\n end\nend" for s in
        ("Willmore flow", "Navier-Stokes") if f"subsection {s}" in text) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cases", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--run", action="store_true")
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--cheap", type=float, default=30)
    ap.add_argument("--binary", default="build/vesicle-iga")
    ap.add_argument("--jobs", type=int, default=1,
                    help="cases run at once (the outcome does not depend on it)")
    ap.add_argument("files", nargs="*")
    a = ap.parse_args()
    binary = os.path.abspath(a.binary)
    files = a.files or sorted(glob.glob("prm/*.prm"))
    sources = {f: open(f, errors="replace").read().split("\n") for f in files}
    rng = random.Random(a.seed)
    counts, findings = {}, []
    work = tempfile.mkdtemp(prefix="fuzz-prm-")
    cheap = {}
    if a.run:
        for f in files:
            path = os.path.join(work, "base.prm")
            open(path, "w").write(few_steps("\n".join(sources[f]))
                                  + "set Output directory = out\n")
            p, t = run([binary, path], a.cheap, work)
            cheap[f] = not t and p.returncode == 0
    # The cases are drawn first, so that the outcome does not depend on
    # --jobs; each runs in a folder of its own (a run locks its output
    # directory).
    cases = []
    for case in range(a.cases):
        f = rng.choice(files)
        lines, what, non_finite = mutate(sources[f], rng)
        cases.append((case, f, "\n".join(lines), what, non_finite))

    def run_case(item):
        case, f, text, what, non_finite = item
        folder = os.path.join(work, f"case-{case}")
        os.makedirs(folder)
        path = os.path.join(folder, "case.prm")
        with open(path, "w", errors="replace") as out:
            out.write(text)
        p, t = run([binary, "--check", path], a.timeout, folder)
        verdict = classify(p, t)
        if verdict == "accepted" and non_finite:
            verdict = "INVALID"
        if verdict == "accepted" and a.run and cheap.get(f):
            with open(path, "w", errors="replace") as out:
                out.write(few_steps(text) + "set Output directory = out\n")
            p, t = run([binary, path], a.timeout, folder)
            verdict = classify(p, t)
            verdict = "ran" if verdict == "accepted" else (
                "refused at run" if verdict == "refused" else verdict)
        shutil.rmtree(folder, ignore_errors=True)
        finding = None
        if verdict in ("CRASH", "HANG", "INVALID"):
            tail = (p.stdout + p.stderr).strip().splitlines()[-3:]
            finding = (f"{verdict}: {os.path.basename(f)}: {what}: exit "
                       f"{p.returncode}: " + " | ".join(tail))
        return verdict, finding

    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        for verdict, finding in pool.map(run_case, cases):
            counts[verdict] = counts.get(verdict, 0) + 1
            if finding:
                findings.append(finding)
    print(f"{a.cases} cases from {len(files)} files (seed {a.seed}): " +
          ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    for line in findings:
        print(line)
    shutil.rmtree(work, ignore_errors=True)
    sys.exit(1 if findings else 0)


if __name__ == "__main__":
    main()
