#!/usr/bin/env python3
"""Compares two folders of JSON summaries kept by bench/shape_hashes.sh (HASH_JSON_DIR=DIR).

    HASH_JSON_DIR=before bench/shape_hashes.sh OLD_TOOL > before.txt
    HASH_JSON_DIR=after  bench/shape_hashes.sh NEW_TOOL > after.txt
    bench/compare_json.py before after

Prints every key whose value changed or that is gone (a refactor that claims no output change must
print none) and every key added; exits 1 if a value changed or a key is gone.
"""
import json
import pathlib
import sys


def walk(old, new, path, changed, added):
    if isinstance(old, dict):
        if not isinstance(new, dict):
            changed.append(f"{path}: an object became {type(new).__name__}")
            return
        for key, value in old.items():
            if key not in new:
                changed.append(f"{path}/{key}: gone")
            else:
                walk(value, new[key], f"{path}/{key}", changed, added)
        added.update(f"{path.split(':', 1)[-1]}/{key}" for key in new if key not in old)
    elif isinstance(old, list):
        if not isinstance(new, list) or len(old) != len(new):
            changed.append(f"{path}: a list of {len(old)} became {new!r:.80}")
            return
        for a, b in zip(old, new):
            walk(a, b, f"{path}[]", changed, added)
    elif old != new:
        changed.append(f"{path}: {old!r} -> {new!r}")


def main():
    before, after = map(pathlib.Path, sys.argv[1:3])
    changed, added = [], set()
    for f in sorted(before.glob("*.json")):
        other = after / f.name
        if not other.exists():
            changed.append(f"{f.name}: missing in {after}")
            continue
        walk(json.loads(f.read_text()), json.loads(other.read_text()), f"{f.stem}:", changed, added)
    print("changed or gone:", *(changed or ["none"]), sep="\n  ")
    print("added:", *(sorted(added) or ["none"]), sep="\n  ")
    return 1 if changed else 0


if __name__ == "__main__":
    sys.exit(main())
