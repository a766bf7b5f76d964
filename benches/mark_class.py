"""A class of 200 students and 10 answers each, marked by `kinetics mark` in one process.

The scheme is the example class's four questions repeated as Q1 to Q10; each student's
answers are the example's (examples/marking/submissions.csv), taken in turn, so right
answers, every planted slip and the carried-forward derivations are all in it. Prints the
wall time of three runs and their best; build first with `cargo build --release`.

    python3 benches/mark_class.py
"""

import csv
import os
import shutil
import subprocess
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
TARGET = os.path.join(ROOT, "target", "mark_class")
STUDENTS, QUESTIONS = 200, 10


def main():
    os.makedirs(TARGET, exist_ok=True)
    example = os.path.join(ROOT, "examples", "marking")
    with open(os.path.join(example, "scheme.toml")) as f:
        scheme = f.read().replace('"../scenes/', '"../../examples/scenes/')
    blocks = scheme.split("[[question]]")
    head, questions = blocks[0], blocks[1:]
    out = [head]
    for k in range(QUESTIONS):
        block = questions[k % len(questions)]
        block = block.replace(f'id = "Q{k % len(questions) + 1}"', f'id = "Q{k + 1}"', 1)
        out.append("[[question]]" + block)
    with open(os.path.join(TARGET, "scheme.toml"), "w") as f:
        f.write("".join(out))
    answers = {}
    with open(os.path.join(example, "submissions.csv"), newline="") as f:
        for row in csv.DictReader(f):
            answers.setdefault(row["question"], []).append(row["answer"])
    with open(os.path.join(TARGET, "submissions.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["student", "question", "answer"])
        for s in range(STUDENTS):
            for k in range(QUESTIONS):
                base = answers[f"Q{k % len(questions) + 1}"]
                w.writerow([f"s{s:03}", f"Q{k + 1}", base[(s * 7 + k) % len(base)]])
    binary = os.path.join(ROOT, "target", "release", "kinetics")
    times = []
    for _ in range(3):
        output = os.path.join(TARGET, "marked")
        shutil.rmtree(output, ignore_errors=True)
        start = time.perf_counter()
        run = subprocess.run(
            [binary, "mark", os.path.join(TARGET, "scheme.toml"),
             os.path.join(TARGET, "submissions.csv"), "-o", output],
            capture_output=True, text=True, check=True)
        times.append(time.perf_counter() - start)
    print(run.stdout.strip())
    print(f"{'run':>5} {'seconds':>9}")
    for k, t in enumerate(times):
        print(f"{k + 1:>5} {t:>9.3f}")
    print(f"{STUDENTS} students x {QUESTIONS} answers: best {min(times):.3f} s on {os.cpu_count()} cores")


if __name__ == "__main__":
    main()
