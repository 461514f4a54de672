#!/usr/bin/env bash
# Sends SIGINT, SIGTERM or SIGHUP at random moments to many `cdvp run`s with
# several outputs, each replacing an old file, and checks that every run
# leaves all its outputs new or all old, with no temporary behind.
#
#   scripts/signal-stress.sh [ITERATIONS]     (default 200; needs build/)
set -euo pipefail
cd "$(dirname "$0")/.."
export CDVP_SIGNAL_STRESS_ITERATIONS="${1:-200}"
exec ./build/tests/cli_tests --gtest_filter='Cli.SignalsAtRandomMomentsLeaveAllOutputsOrNone'
