"""Checks that no dependency the crate builds for its users (normal
dependencies, default features) declares a `rust-version` above the crate's
own, so that the declared minimum supported Rust version is one the whole
build accepts. (The machine has one toolchain, so the MSRV cannot be built;
clippy's `incompatible_msrv` lint checks the crate's own use of the standard
library against it.)

Usage: python3 .ci/msrv.py MANIFEST...
"""

import json
import subprocess
import sys


def version(text):
    return tuple(int(part) for part in text.split(".")[:2])


def check(manifest):
    metadata = json.loads(subprocess.run(
        ["cargo", "metadata", "--format-version", "1", "--manifest-path", manifest],
        check=True, capture_output=True, text=True).stdout)
    root = next(p for p in metadata["packages"] if p["manifest_path"].endswith(manifest.split("/")[-1])
                and p["id"] in metadata["workspace_members"])
    ours = root["rust_version"]
    tree = subprocess.run(
        ["cargo", "tree", "-e", "normal", "--prefix", "none", "--manifest-path", manifest],
        check=True, capture_output=True, text=True).stdout
    used = {tuple(line.split()[:2]) for line in tree.splitlines() if line.strip()}
    failures = []
    for package in metadata["packages"]:
        wanted = package.get("rust_version")
        if (package["name"], "v" + package["version"]) in used and wanted \
                and version(wanted) > version(ours):
            failures.append(f"{package['name']} {package['version']} needs Rust {wanted}")
    print(f"{root['name']}: rust-version {ours}, {len(used)} normal dependencies checked")
    return failures


failures = [f for manifest in sys.argv[1:] for f in check(manifest)]
if failures:
    print("dependencies above the declared rust-version:\n  " + "\n  ".join(failures))
    sys.exit(1)
