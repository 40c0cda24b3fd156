"""Reading OpenFOAM's ASCII fields and logs (standard library only; the runs write ASCII)."""
import os
import re


def latest_time(case):
    """The name of the case's latest time directory other than 0."""
    times = []
    for name in os.listdir(case):
        try:
            t = float(name)
        except ValueError:
            continue
        if t > 0 and os.path.isdir(os.path.join(case, name)):
            times.append((t, name))
    if not times:
        raise FileNotFoundError(f"{case}: no results (no time directory after 0)")
    return max(times)[1]


def _closing(text, start):
    """Index of the parenthesis that closes the one at start."""
    depth = 0
    for i in range(start, len(text)):
        if text[i] == "(":
            depth += 1
        elif text[i] == ")":
            depth -= 1
            if depth == 0:
                return i
    raise ValueError("unbalanced parentheses")


def _value(text, pos):
    """The field value that starts at pos: a list for nonuniform, a number or tuple for
    uniform."""
    m = re.compile(r"\s*(uniform|nonuniform)\s*").match(text, pos)
    if m is None:
        raise ValueError(f"no field value at {text[pos:pos + 40]!r}")
    pos = m.end()
    if m.group(1) == "uniform":
        if text[pos] == "(":
            end = _closing(text, pos)
            return tuple(float(x) for x in text[pos + 1:end].split())
        return float(re.compile(r"[^;\s]+").match(text, pos).group(0))
    m = re.compile(r"List<(\w+)>\s*(\d+)\s*").match(text, pos)
    kind, n, pos = m.group(1), int(m.group(2)), m.end()
    end = _closing(text, pos)
    body = text[pos + 1:end]
    if kind == "scalar":
        vals = [float(x) for x in body.split()]
    else:
        vals = [tuple(float(x) for x in v.split()) for v in re.findall(r"\(([^()]*)\)", body)]
    if len(vals) != n:
        raise ValueError(f"list of {n} with {len(vals)} values")
    return vals


def internal(path):
    """The internal field of an ASCII volField file."""
    text = open(path).read()
    return _value(text, text.index("internalField") + len("internalField"))


def patch_value(path, patch):
    """The value entry of one patch of an ASCII volField file."""
    text = open(path).read()
    pos = text.index("boundaryField")
    m = re.compile(r"\b" + re.escape(patch) + r"\s*\{").search(text, pos)
    if m is None:
        raise ValueError(f"{path}: no patch {patch}")
    v = re.compile(r"\bvalue\b").search(text, m.end())
    return _value(text, v.end())


def grep(path, pattern):
    """Every match of pattern in the file (first group if any)."""
    if not os.path.exists(path):
        return []
    return re.findall(pattern, open(path).read())
