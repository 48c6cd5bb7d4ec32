#!/usr/bin/python3
"""Runs every command of README.md and of the docs pages' shell code blocks, as written, in a clean
clone of the repository in a scratch folder, and checks the counts the text claims for them.

Usage: scripts/readme_check.py [--bin DIR] [--python DIR] [--timings FILE] [--keep]

  --bin DIR       the built commands (default: build/bin of this checkout)
  --python DIR    the built Python module (default: build/python, when it exists)
  --timings FILE  also write the seconds each command took as JSON (README timings come from it)
  --keep          keep the scratch folder

Every line of a ```sh block (continuation lines joined, comments kept for the claims) is run
with bash in the clone, where build/bin and build/python point at the given builds, `fspm` is on
PATH and PYTHONPATH holds the module; ```python blocks run with /usr/bin/python3. A command is
skipped only when SKIPPED below names it with the reason. A claim (CLAIMS) ties a number in the
text to the command's output: the text must still say it and the output must agree. Exits 1 when a
command fails, a claim differs or a claim's text is no longer in the pages.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.realpath(os.path.join(os.path.dirname(__file__), ".."))
PAGES = ["README.md", "docs/crown.md", "docs/experiments.md", "docs/graphics.md",
         "docs/greenlab.md", "docs/lsystem-language.md"]

# Commands that are not run, matched by a regular expression on the command, with the reason.
SKIPPED = [
    (r"^scripts/demo\.sh", "installs dependencies and builds (minutes); its experiment is the "
     "tour's adapted-versus-grown run, which is run here"),
    (r"^scripts/test\.sh", "runs this check"),
    (r"^scripts/package\.sh", "needs root for apt; scripts/test.sh builds the package and "
     "checks it with scripts/package_check.sh"),
    (r"^cmake (-S \. -B build|--build build|--install)", "the build and install of fspm itself, "
     "done by scripts/test.sh (install: scripts/downstream_check.sh, into a scratch prefix)"),
    (r"^cmake (-S|--build) (examples/downstream|build-downstream)", "scripts/downstream_check.sh "
     "builds examples/downstream against an installed fspm"),
    (r"^build-downstream/", "built by scripts/downstream_check.sh, which runs it"),
    (r"^pip install", "installs into the Python environment; the module is built by CMake here"),
    (r"(^|xvfb-run -a )(\$fspm|fspm) view ", "opens a window to look at (the viewer is tested "
     "under Xvfb with --screenshot by CTest)"),
    (r"^for i in \$\(seq 0 23\)", "24 renders of a wind movie (minutes); --wind-time is tested "
     "by the graphics tests"),
    (r"^oiiotool frame_", "joins the frames of the skipped wind movie"),
    (r"^xvfb-run -a scripts/impostor_figure\.sh", "the figure script of a docs image (minutes)"),
    (r"^xvfb-run -a fspm render examples/landscape/landscape\.json .*--size 1280x800",
     "the README's landscape render, run there (a minute on 2 cores)"),
]

# Claims: a command (regular expression), the text the pages must still contain, and a function
# of the command's output (stdout and stderr) and working folder that returns the value found.
def _json(out):
    start = out.find("{")
    return json.loads(out[start:out.rfind("}") + 1])


def _int_after(pattern):
    def find(out, _cwd):
        m = re.search(pattern, out)
        return int(m.group(1)) if m else None
    return find


CLAIMS = [
    (r"lsystem derive examples/lsystems/abop_1_24a\.l --json$", '"F": 3125, 7811 modules',
     lambda out, _: (_json(out)["symbols"]["F"], _json(out)["modules"]), (3125, 7811)),
    (r"interpret examples/lsystems/abop_1_24a\.l --compressed --steps 7 -o fig124a\.glb --json",
     "8 prototypes, 15 625 instances",
     lambda out, _: (_json(out)["prototypes"], _json(out)["instances"]), (8, 15625)),
    (r"tree info tree\.tree$", "1023 internodes", _int_after(r"internodes: (\d+)"), 1023),
    (r"tree info measured\.tree$", "198 shoots", _int_after(r"nodes: (\d+)"), 198),
    (r"scan examples/trees/open_a12\.treeb", "73 843 points, 4 scanners",
     lambda out, _: tuple(int(x) for x in
                          re.search(r"(\d+) points from (\d+) scanner", out).groups()),
     (73843, 4)),
    (r"encode scan\.ply .*-o tree\.clusters", "138 leaf clusters",
     _int_after(r"(\d+) clusters"), 138),
    (r"stats ttest examples/stats/plant_growth_ctrl\.csv", "t = -2.134, df = 16.79, p = 0.0479",
     lambda out, _: tuple(round(_json(out)[k], n) for k, n in (("t", 3), ("df", 2), ("p", 4))),
     (-2.134, 16.79, 0.0479)),
    (r"run examples/experiments/branching\.toml --out sweep", "A sweep: 36 runs",
     _int_after(r"(\d+) runs \("), 36),
    (r"run examples/experiments/wall_distance\.toml", "5 distances x 3 pruning strengths",
     _int_after(r"(\d+) runs \("), 15),
    (r"report avg --html --single-file", "avg/report.html (one file)",
     lambda _, cwd: os.path.getsize(os.path.join(cwd, "avg", "report.html")) < 20e6, True),
    (r"run examples/experiments/adapted_vs_grown\.toml --replicates 4", "# 108 runs",
     _int_after(r"(\d+) runs \("), 108),
]


def blocks(page):
    """(language, first line number, lines) of each ```sh, ```bash and ```python block."""
    found, lang, start, lines = [], None, 0, []
    with open(os.path.join(ROOT, page), encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if lang is None:
                m = re.match(r"^```(sh|bash|python)\s*$", line)
                if m:
                    lang, start, lines = m.group(1), number + 1, []
            elif line.startswith("```"):
                found.append((lang, start, lines))
                lang = None
            else:
                lines.append(line.rstrip("\n"))
    return found


def commands(lines, first):
    """Shell lines joined at backslashes and over a multi-line for/while/if: (line, command,
    comment)."""
    out, pending, at, compound = [], "", first, None
    for i, line in enumerate(lines):
        if not pending and compound is None:
            at = first + i
        if line.endswith("\\"):
            pending += line[:-1] + " "
            continue
        code, comment = split_comment(pending + line)
        pending = ""
        if compound is not None:
            compound = (compound[0] + "\n" + code, compound[1] or comment)
            if re.match(r"^\s*(done|fi)\b", code):
                out.append((at, compound[0], compound[1]))
                compound = None
            continue
        if re.match(r"^(for|while|if) ", code) and not re.search(r"\b(done|fi)\b", code):
            compound = (code, comment)
            continue
        if code.strip():
            out.append((at, " ".join(code.split()), comment))
    return out


def split_comment(text):
    """The command and its trailing comment (a # outside quotes, after a space)."""
    quote = None
    for i, c in enumerate(text):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c == "#" and (i == 0 or text[i - 1] in " \t"):
            return text[:i], text[i + 1:].strip()
    return text, ""


def is_synopsis(command):
    """A usage line (options in brackets, alternatives of capitalised placeholders)."""
    return "[--" in command or re.search(r"\b[A-Z]{2,}[.A-Z]*\|", command) is not None


def run(command, cwd, env, lang):
    began = time.monotonic()
    if lang == "python":
        proc = subprocess.run(["/usr/bin/python3", "-c", command], cwd=cwd, env=env,
                              capture_output=True, text=True)
    else:
        proc = subprocess.run(["bash", "-euo", "pipefail", "-c", command], cwd=cwd, env=env,
                              capture_output=True, text=True)
    return proc.returncode, proc.stdout + proc.stderr, time.monotonic() - began


def check_claims(page_text, command, out, cwd):
    problems = []
    for pattern, text, value, expected in CLAIMS:
        if not re.search(pattern, command):
            continue
        if text not in page_text:
            problems.append(f"the pages no longer say '{text}'; update CLAIMS")
            continue
        try:
            found = value(out, cwd)
        except (ValueError, KeyError, AttributeError, TypeError) as e:
            found = f"unreadable output ({e})"
        if found != expected:
            problems.append(f"claims '{text}' ({expected}), the output gives {found}")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    parser.add_argument("--python", default=os.path.join(ROOT, "build", "python"))
    parser.add_argument("--timings")
    parser.add_argument("--keep", action="store_true")
    args = parser.parse_args()
    binary = os.path.realpath(args.bin)
    if not os.access(os.path.join(binary, "fspm"), os.X_OK):
        sys.exit(f"readme_check: no fspm in {binary}; build first or give --bin")
    python = os.path.realpath(args.python) if os.path.isdir(args.python) else None

    scratch = tempfile.mkdtemp(prefix="fspm-readme-")
    clone = os.path.join(scratch, "fspm")
    subprocess.run(["git", "clone", "-q", "--no-hardlinks", ROOT, clone], check=True)
    os.makedirs(os.path.join(clone, "build"))
    os.symlink(binary, os.path.join(clone, "build", "bin"))
    if python:
        os.symlink(python, os.path.join(clone, "build", "python"))
    # python3 is Debian's (/usr/bin first), with numpy, as on the machines the README is for.
    env = dict(os.environ, PATH=os.pathsep.join([binary, "/usr/bin", os.environ.get("PATH", "")]),
               HOME=os.path.join(scratch, "home"))
    if python:
        env["PYTHONPATH"] = python
    os.makedirs(env["HOME"])

    all_text = "".join(open(os.path.join(ROOT, p), encoding="utf-8").read() for p in PAGES)
    failures, timings, ran, skipped = [], [], 0, 0
    for page in PAGES:
        for lang, first, lines in blocks(page):
            if lang == "python":
                pending = [(first, "\n".join(lines), "")]
                if not python:
                    print(f"skip  {page}:{first} python block: the Python module is not built")
                    skipped += 1
                    continue
            else:
                pending = commands(lines, first)
            for line, command, comment in pending:
                where = f"{page}:{line}"
                shown = command.splitlines()[0][:100]
                m = re.match(r"^(\w+)=(\S+)$", command)
                if m:  # a variable the block's later lines use
                    env[m.group(1)] = m.group(2)
                    continue
                reason = next((r for p, r in SKIPPED if re.search(p, command)), None)
                if reason is None and is_synopsis(command):
                    reason = "a usage line, not a command"
                if reason:
                    print(f"skip  {where} {shown}: {reason}")
                    skipped += 1
                    continue
                code, out, seconds = run(command, clone, env, lang)
                ran += 1
                timings.append({"page": page, "line": line, "command": command,
                                "seconds": round(seconds, 2)})
                if code != 0:
                    failures.append(f"{where}: exit {code}: {shown}\n{out[-1500:]}")
                    print(f"FAIL  {where} {shown} ({seconds:.1f} s, exit {code})")
                    continue
                problems = check_claims(all_text, command, out, clone)
                for p in problems:
                    failures.append(f"{where}: {shown}: {p}")
                print(f"{'FAIL' if problems else 'ok'}    {where} {shown} ({seconds:.1f} s)")

    if args.timings:
        with open(args.timings, "w", encoding="utf-8") as f:
            json.dump(timings, f, indent=1)
    if args.keep:
        print(f"scratch folder kept: {scratch}")
    else:
        shutil.rmtree(scratch, ignore_errors=True)
    total = sum(t["seconds"] for t in timings)
    print(f"readme_check: {ran} commands run in {total:.0f} s, {skipped} skipped, "
          f"{len(failures)} failures")
    for f in failures:
        print("\n" + f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
