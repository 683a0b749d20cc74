#!/usr/bin/env bash
source "$(dirname "$0")/lib.sh"

expect_exit 0 "rts --help" -- "$RTS" --help
expect_grep "$TMP/out" "render" "--help lists the render command"
expect_grep "$TMP/out" "parse" "--help lists the parse command"
for c in parse check eval render converge fmt; do
  expect_exit 0 "rts $c --help" -- "$RTS" $c --help
  expect_grep "$TMP/out" "Usage" "rts $c --help prints usage"
done
expect_exit 0 "rts --version" -- "$RTS" --version
expect_grep "$TMP/out" "^rts [0-9]+\.[0-9]+\.[0-9]+" "--version prints the version"

expect_exit 2 "unknown global flag" -- "$RTS" --frobnicate
expect_grep "$TMP/err" "frobnicate" "the message names the unknown flag"
expect_exit 2 "unknown command flag" -- "$RTS" render --frobnicate x.rts
expect_grep "$TMP/err" "frobnicate" "the message names the unknown flag"
expect_exit 2 "no command" -- "$RTS"
expect_exit 2 "unknown command" -- "$RTS" paint x.rts
expect_exit 2 "missing scene argument" -- "$RTS" render
finish
