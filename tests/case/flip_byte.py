#!/usr/bin/env python3
"""Flips one bit of a checkpoint: in the data of /fields/pos (its address from h5ls -va), or in
the root attribute "time" (the 8 bytes of its value, after its name in the file). Standard library only.
    flip_byte.py CHECKPOINT pos|time"""
import re
import struct
import subprocess
import sys

path, what = sys.argv[1], sys.argv[2]
data = bytearray(open(path, "rb").read())
if what == "pos":
    info = subprocess.run(["h5ls", "-va", path + "/fields/pos"], capture_output=True, text=True,
                          check=True).stdout
    m = re.search(r"Address:\s*(\d+)", info)
    if m is None:
        sys.exit("no address of /fields/pos in h5ls -va:\n" + info)
    at = int(m.group(1)) + 5
else:
    t = subprocess.run(["h5dump", "-a", "/time", path], capture_output=True, text=True,
                       check=True).stdout
    value = float(re.search(r"\(0\): ([-0-9.eE+]+)", t).group(1))
    # the attribute's message holds its name, then its type and shape, then its value
    name = bytes(data).find(b"time\x00")
    at = bytes(data).find(struct.pack("<d", value), name)
    if name < 0 or at < 0 or at - name > 128:
        sys.exit(f"the attribute time = {value} is not where it should be in the file")
    at += 3
data[at] ^= 0x10
open(path, "wb").write(bytes(data))
