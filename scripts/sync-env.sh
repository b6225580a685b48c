#!/bin/sh
# Usage: sync-env.sh UV [uv sync arguments...]
# Runs `UV sync ARGS`, unless a dry run says it would change nothing (no package to add or remove,
# no environment to create or replace): then nothing runs, so an up-to-date .venv is not touched
# and no bytecode is compiled again.
uv=$1
shift
plan=$("$uv" sync --dry-run "$@" 2>&1)
if printf '%s\n' "$plan" | grep -q '^Would make no changes' &&
    ! printf '%s\n' "$plan" | grep -q '^Would \(create\|replace\|remove\)'; then
    echo ".venv is up to date (uv sync $* would change nothing)"
else
    exec "$uv" sync "$@"
fi
