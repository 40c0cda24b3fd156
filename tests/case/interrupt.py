#!/usr/bin/env python3
"""SIGINT and SIGTERM during `clsph run` (standard library only; h5diff from hdf5-tools).
 1. SIGINT: the step ends, a checkpoint of the state reached and summary.json (status
    "interrupted (SIGINT) ...", failure "interrupted") are written, exit status 130; the run resumed
    from that checkpoint in its folder ends bit for bit where an uninterrupted run ends.
 2. SIGTERM: the same with exit status 143.
 3. SIGINT in a case script's long metrics(): it stops there (the sandbox's hook), not after its
    budget; summary.json says so, exit status 130.
 4. A second signal while the first is served: it exits at once (no checkpoint, no summary),
    exit status 128 + the second's number.
    interrupt.py CLSPH SOURCE_DIR OUT"""
import json
import os
import shutil
import signal
import subprocess
import sys
import time

clsph, src, out = sys.argv[1], sys.argv[2], sys.argv[3]
drift = os.path.join(src, "tests", "case", "drift.lua")
failed = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failed.append(what)


def start(case, folder, *sets):
    args = [clsph, "run", case, "--out", folder, "--quiet"]
    for s in sets:
        args += ["--set", s]
    return subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def wait_for(path, p, seconds=60):
    end = time.time() + seconds
    while not os.path.exists(path):
        if p.poll() is not None or time.time() > end:
            sys.exit(f"{path} did not appear (exit status {p.poll()}): {p.communicate()[0]}")
        time.sleep(0.02)


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)

# 1 and 2: a graceful stop at a checkpoint, then a bit-for-bit resume
for sig, name, rc_want in ((signal.SIGINT, "SIGINT", 130), (signal.SIGTERM, "SIGTERM", 143)):
    folder = os.path.join(out, name)
    p = start(drift, folder)
    wait_for(os.path.join(folder, "snap_000002.h5"), p)
    p.send_signal(sig)
    text = p.communicate(timeout=60)[0]
    print(text)
    check(p.returncode == rc_want, f"{name}: exit status {p.returncode} (want {rc_want})")
    s = summary(folder)
    check(s["status"].startswith(f"interrupted ({name}) at step {s['steps']},") and
          s["failure"] == "interrupted", f"{name}: summary.json status '{s['status']}'")
    ck = os.path.join(folder, "checkpoint_%06d.h5" % s["steps"])
    check(os.path.exists(ck), f"{name}: the checkpoint of the state reached, {ck}")
    check("--restart " + ck in text, f"{name}: the message says how to resume")
    if sig != signal.SIGINT:
        continue
    # resume to the next two outputs after the interruption; the same run uninterrupted
    t_end = (int(s["sim_time"] // 100) + 2) * 100
    r = subprocess.run([clsph, "run", drift, "--set", f"t_end={t_end}", "--restart", ck, "--out",
                        folder, "--quiet"], capture_output=True, text=True)
    check(r.returncode == 0, f"resumed run: exit status {r.returncode} {r.stderr}")
    whole = os.path.join(out, "whole")
    r = subprocess.run([clsph, "run", drift, "--set", f"t_end={t_end}", "--out", whole,
                        "--quiet"], capture_output=True, text=True)
    check(r.returncode == 0, f"uninterrupted run: exit status {r.returncode} {r.stderr}")
    last = "checkpoint_%06d.h5" % summary(whole)["steps"]
    d = subprocess.run(["h5diff", os.path.join(whole, last), os.path.join(folder, last), "/fields",
                        "/fields"], capture_output=True, text=True)
    check(d.returncode == 0, f"resumed final state {last} equals the uninterrupted run's, bit for "
          f"bit {d.stdout}")
    check(summary(folder)["metrics"] == summary(whole)["metrics"], "resumed metrics agree")

# 3: SIGINT in metrics(): it ends there, well before its 2 s budget
folder = os.path.join(out, "metrics")
p = start(drift, folder, "t_end=200", "slow=1")
wait_for(os.path.join(folder, "snap_000002.h5"), p)
time.sleep(0.3)
t0 = time.time()
p.send_signal(signal.SIGINT)
text = p.communicate(timeout=60)[0]
print(text)
check(time.time() - t0 < 1.0 and "metrics() interrupted (SIGINT)" in text,
      f"metrics() stopped by SIGINT within {time.time() - t0:.2f} s")
s = summary(folder)
check(p.returncode == 130 and s["status"] == "interrupted (SIGINT) while metrics() ran" and
      s["failure"] == "interrupted",
      f"metrics() interrupted: exit status {p.returncode}, summary.json status '{s['status']}'")

# 4: a second signal while the first is being served: it exits at once. The run is stopped
# (SIGSTOP) while SIGINT and SIGTERM are sent, and continued: both are then pending and arrive
# one right after the other, however busy the machine (signals of one kind do not queue, two
# kinds do), so the second always finds the first being served.
folder = os.path.join(out, "twice")
p = start(drift, folder)
wait_for(os.path.join(folder, "snap_000001.h5"), p)
t0 = time.time()
p.send_signal(signal.SIGSTOP)
p.send_signal(signal.SIGINT)
p.send_signal(signal.SIGTERM)
p.send_signal(signal.SIGCONT)
text = p.communicate(timeout=60)[0]
print(text)
check(p.returncode in (130, 143) and "interrupted again: exiting at once" in text,
      f"a second signal exits at once: exit status {p.returncode}, {time.time() - t0:.2f} s")
check(not os.path.exists(os.path.join(folder, "summary.json")),
      "a second signal leaves no summary.json")

shutil.rmtree(out, ignore_errors=True)
sys.exit(1 if failed else 0)
