#!/usr/bin/env bash
# Record the golden outputs (benchmarks/golden.py) of two commits on this
# machine and compare them bit for bit: bash benchmarks/golden_compare.sh OLD [NEW]
# (NEW defaults to the work tree).  Each commit is measured from a worktree of
# its own, with its own golden.py where it has one (else this one).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
old="${1:?usage: golden_compare.sh OLD [NEW]}"
new="${2:-}"
tmp="$(mktemp -d)"
trap 'git -C "$here" worktree remove --force "$tmp/old" >/dev/null 2>&1 || true; [ -n "$new" ] && git -C "$here" worktree remove --force "$tmp/new" >/dev/null 2>&1 || true; rm -rf "$tmp"' EXIT
record() {  # record REV_DIR OUT
    local script="$1/benchmarks/golden.py"
    [ -f "$script" ] || script="$here/benchmarks/golden.py"
    python "$script" --root "$1" --write "$2"
}
git -C "$here" worktree add --detach "$tmp/old" "$old" >/dev/null
record "$tmp/old" "$tmp/old.json"
if [ -n "$new" ]; then
    git -C "$here" worktree add --detach "$tmp/new" "$new" >/dev/null
    record "$tmp/new" "$tmp/new.json"
else
    record "$here" "$tmp/new.json"
fi
python - "$tmp/old.json" "$tmp/new.json" <<'PY'
import json, sys
sys.path.insert(0, sys.argv[0] and "benchmarks")
from golden import compare
a, b = (json.load(open(p)) for p in sys.argv[1:3])
d = compare(a, b, 0.0)
print("\n".join(d[:50]))
print(f"{len(d)} differences, bit for bit")
sys.exit(1 if d else 0)
PY
