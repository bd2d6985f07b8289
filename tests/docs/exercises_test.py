#!/usr/bin/env python3
"""Every exercise of the exercises file, judged by `lightpath lpe exercise` three times from the
file's own `test` fields: `right` and `equivalent` must be judged right (exit 0, "right:"), and
`wrong` judged wrong (exit 1, "not yet:") with the side that accepts more as the file states it
(decided by hand, not by the engine): "yours", "answer" or "both". One wrong answer in N is also
rendered (`--render-every N`), and its difference image must be written with a mean printed.

    exercises_test.py --lightpath BIN --source SOURCE_DIR --work DIR [--render-every N]
"""
import argparse
import os
import re
import subprocess
import sys
import tomllib

TOO_MUCH = "is accepted by yours, not by the answer"
MISSES = "is accepted by the answer, not by yours"


def judge(lightpath, source, work, exercise, answer, render):
    argv = [lightpath, "lpe", "exercise", os.path.join(source, "lectures/exercises.toml"),
            "--question", exercise["id"], "--answer", answer]
    argv += ["--resolution", "32x24", "--spp", "1", "-o", os.path.join(work, "exercise")] if render else ["--no-render"]
    done = subprocess.run(argv, cwd=source, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return done.returncode, done.stdout


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lightpath", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--render-every", type=int, default=4)
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    with open(os.path.join(args.source, "lectures/exercises.toml"), "rb") as f:
        exercises = tomllib.load(f)["exercise"]
    failures = []
    for index, exercise in enumerate(exercises):
        test = exercise["test"]
        for kind in ("right", "equivalent"):
            code, output = judge(args.lightpath, args.source, args.work, exercise, test[kind], False)
            if code != 0 or not output.startswith("right:"):
                failures.append(f"{exercise['id']}: {kind} answer {test[kind]!r} not judged right (exit {code}):\n{output}")
        render = index % args.render_every == 0
        code, output = judge(args.lightpath, args.source, args.work, exercise, test["wrong"], render)
        side = test["wrong_side"]
        sides_ok = (TOO_MUCH in output) == (side in ("yours", "both")) and (MISSES in output) == (side in ("answer", "both"))
        if code != 1 or not output.startswith("not yet:") or not sides_ok:
            failures.append(f"{exercise['id']}: wrong answer {test['wrong']!r} (side {side}) misjudged (exit {code}):\n{output}")
        if render:
            image = os.path.join(args.work, f"exercise-{exercise['id']}.yours-only.png")
            if not re.search(r"yours-only mean [0-9.e+-]+, answer-only mean", output) or not os.path.exists(image):
                failures.append(f"{exercise['id']}: no difference render (expected {image}):\n{output}")
        print(f"{exercise['id']}: checked", flush=True)
    if len(exercises) < 15:
        failures.append(f"only {len(exercises)} exercises; the lecture needs at least 15")
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
