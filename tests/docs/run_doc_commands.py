#!/usr/bin/env python3
"""Runs every command a page shows, as it is written, so the docs cannot drift from the program.

    run_doc_commands.py --lightpath BIN --source SOURCE_DIR --work DIR PAGE.md...

Commands are read from the pages' fenced code blocks: in a block with `$ ` prompts each prompt
line is a command and the lines after it, up to the next prompt, are its output as pasted; in a
block without prompts every line is a command (a trailing `# comment` is dropped); in prose, an
inline code span that starts with `build/lightpath` is a command too. Each runs
under bash (pipefail) in DIR, where `build/lightpath` is BIN and the repository's scenes,
lectures and tests are linked, so `out/...` outputs land in DIR.

What is checked: the exit code is 0 (1 for an `lpe exercise` whose pasted output starts with
"not yet": a wrong answer), and every pasted output line but `...` occurs, trailing spaces aside,
in what the command printed (stdout and stderr). Changes to the commands as written, stated here:
- commands that start with `scripts/` (set-up and the whole test suite, this test included) and
  `cmake` commands (building) are not run: the build that runs this test has run them; of
  `scripts/setup && COMMAND`, COMMAND is run;
- `serve` gets `--port 0` appended (any free port: 8080 may be taken on a shared machine); it runs
  until it prints its URL, then gets SIGINT and must exit.
"""
import argparse
import os
import re
import shlex
import signal
import subprocess
import sys

FENCE = re.compile(r"^\s*(```|~~~)(\w*)")
NOT_RUN = ("scripts/", "cmake ")


def commands(page):
    """(line number, command, pasted output lines) of every command the page shows."""
    found = []
    block, language = None, ""
    for number, line in enumerate(open(page, encoding="utf-8").read().split("\n"), 1):
        if block is None and not FENCE.match(line):
            found.extend((number, span, []) for span in re.findall(r"`(build/lightpath [^`]+)`", line))
        m = FENCE.match(line)
        if m and block is None:
            block, language = [], m.group(2)
            continue
        if m:
            if language in ("", "sh", "console", "bash", "shell"):
                found.extend(commands_of(block))
            block = None
            continue
        if block is not None:
            block.append((number, line))
    return found


def commands_of(block):
    prompts = [i for i, (_, line) in enumerate(block) if line.startswith("$ ")]
    if prompts:
        result = []
        for k, i in enumerate(prompts):
            end = prompts[k + 1] if k + 1 < len(prompts) else len(block)
            output = [line for _, line in block[i + 1:end]]
            result.append((block[i][0], block[i][1][2:], output))
        return result
    result = []
    for number, line in block:
        command = re.sub(r"\s+#\s.*$", "", line).strip()
        if command and not command.startswith("#"):
            result.append((number, command, []))
    return result


def prepare(work, source, lightpath):
    os.makedirs(os.path.join(work, "build"), exist_ok=True)
    links = {"build/lightpath": lightpath}
    for name in ("scenes", "lectures", "tests", "docs"):
        links[name] = os.path.join(source, name)
    for name, target in links.items():
        path = os.path.join(work, name)
        if os.path.lexists(path):
            os.remove(path)
        os.symlink(target, path)


def run_serve(command, work):
    argv = shlex.split(command) + ["--port", "0"]
    process = subprocess.Popen(argv, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    printed = []
    for line in process.stdout:  # blocks until the server prints its URL (or exits)
        printed.append(line)
        if "http://" in line:
            process.send_signal(signal.SIGINT)
            break
    rest, _ = process.communicate()
    printed.append(rest)
    url = any("http://" in line for line in printed)
    return (process.returncode if url else 1), "".join(printed)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lightpath", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("pages", nargs="+")
    args = parser.parse_args()
    prepare(args.work, os.path.abspath(args.source), os.path.abspath(args.lightpath))
    failures, ran = [], 0
    for page in args.pages:
        for number, command, pasted in commands(os.path.join(args.source, page)):
            where = f"{page}:{number}"
            command = re.sub(r"^scripts/setup && ", "", command)
            if command.startswith(NOT_RUN):
                print(f"{where}: not run (see the header): {command}")
                continue
            if not command.startswith("build/lightpath"):
                failures.append(f"{where}: a command this test does not know how to run: {command}")
                continue
            ran += 1
            print(f"{where}: {command}", flush=True)
            if shlex.split(command)[1] == "serve":
                code, output = run_serve(command, args.work)
            else:
                done = subprocess.run(["bash", "-o", "pipefail", "-c", command], cwd=args.work,
                                      stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
                code, output = done.returncode, done.stdout
            wrong_answer = " lpe exercise " in command and pasted and pasted[0].startswith("not yet")
            expected = 1 if wrong_answer else 0
            if code != expected:
                failures.append(f"{where}: exit code {code}, expected {expected}: {command}\n{output}")
            printed = {line.rstrip() for line in output.split("\n")}
            for line in pasted:
                if line.strip() == "..." or not line.strip():
                    continue
                if line.rstrip() not in printed:
                    failures.append(f"{where}: the page shows a line the command does not print:\n"
                                    f"  {line.rstrip()}\n-- it printed:\n{output}")
    print(f"{ran} commands run")
    for f in failures:
        print("FAIL", f)
    return 1 if failures or ran == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
