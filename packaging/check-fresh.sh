#!/usr/bin/env bash
# ./touchline package --check-fresh (or packaging/check-fresh.sh [DEB]): issue 17's "done when", run on demand.
#
# Builds a minimal Debian 12 root with debootstrap (no Java, no Maven: checked), installs the .deb there with
# `apt-get install ./touchline_*.deb` (so its Depends are resolved from the archive: a missing one fails here),
# then inside the root: `touchline --version`, a headless `record` of the packaged simulated robot, `replay
# --headless` of that recording and of the packaged sample, and the window of the desktop entry's command on
# an Xvfb display (Xvfb installed into the root for the check only) with a screenshot. Needs root (debootstrap,
# chroot, mounts) and a Debian mirror (TOUCHLINE_DEBIAN_MIRROR, default the one in /etc/apt/sources*); takes
# minutes. Not part of ./touchline test. The result (what passed, how long) goes to target/fresh-check/:
# result.txt, window.png, and the logs of each step. --keep leaves the root in place (mounted) for a look
# or for `./touchline bench start --root DIR`, the installed start measured.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
. "$ROOT/packaging/colour.sh"
say() { printf '%s %s\n' "$(paint err '1;34' '[touchline check-fresh]')" "$*" >&2; }
die() { printf '%s %s\n' "$(paint err '1;31' '[touchline check-fresh]')" "$*" >&2; exit 1; }

KEEP=0
DEB=""
while [ $# -gt 0 ]; do
  case "$1" in
    --keep) KEEP=1; shift ;;
    -*) die "unknown option $1 (packaging/check-fresh.sh [--keep] [DEB])" ;;
    *) DEB=$1; shift ;;
  esac
done
VERSION=$(sed -n 's/^version=//p' target/classes/touchline/version.properties 2>/dev/null || true)
[ -n "$DEB" ] || DEB="target/package/touchline_${VERSION}_amd64.deb"
[ -f "$DEB" ] || die "$DEB missing: ./touchline package builds it"
[ "$(id -u)" = 0 ] || die "needs root (debootstrap, chroot and mounts): sudo $0"
SUITE=${TOUCHLINE_DEBIAN_SUITE:-bookworm}
MIRROR=${TOUCHLINE_DEBIAN_MIRROR:-$(sed -n 's/^URIs: *\([^ ]*debian\)$/\1/p' /etc/apt/sources.list.d/debian.sources 2>/dev/null | head -1)}
MIRROR=${MIRROR:-http://deb.debian.org/debian}
if ! command -v debootstrap >/dev/null; then
  say "installing debootstrap (apt-get)"
  apt-get install -y -q debootstrap >/dev/null || die "could not install debootstrap"
fi
command -v import >/dev/null || die "import (ImageMagick) missing on this machine: it takes the window's screenshot"

OUT="$ROOT/target/fresh-check"
CACHE="$ROOT/target/fresh-check-debs" # debootstrap's downloads, kept between runs (the root itself is new each time)
rm -rf "$OUT"; mkdir -p "$OUT" "$CACHE"
FRESH=$(mktemp -d /tmp/touchline-fresh.XXXXXX)
PASSED=()
FAILED=()
T0=$(date +%s)
XVFB_PID=""
ROBOT=""
CONSOLE=""
cleanup() {
  for pid in $CONSOLE $ROBOT $XVFB_PID; do kill "$pid" 2>/dev/null || true; done
  if [ "$KEEP" = 1 ]; then
    say "the root is kept in $FRESH with /proc and /dev mounted (xvfb-run -a ./touchline bench start --root $FRESH);" \
      "remove it with: umount $FRESH/proc $FRESH/dev/pts $FRESH/dev && rm -rf $FRESH"
  else
    for m in dev/pts dev proc; do umount -l "$FRESH/$m" 2>/dev/null || true; done
    # never remove through a mount that is still there (the bind mount is the machine's own /dev)
    if grep -q " $FRESH/" /proc/mounts; then
      say "$FRESH still has mounts (see /proc/mounts): not removed"
    else
      rm -rf "$FRESH"
    fi
  fi
}
trap cleanup EXIT
# a command in the root; `in_root CMD &` would make $! a subshell's, so background ones use "${IN_ROOT[@]}" CMD &
# (chroot and env exec the command: $! is then its own process id)
IN_ROOT=(chroot "$FRESH" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin
  HOME=/root LANG=C.UTF-8 DEBIAN_FRONTEND=noninteractive)
in_root() { "${IN_ROOT[@]}" "$@"; }
step() { # name seconds-before; records a passed step with its time
  PASSED+=("$1 ($(( $(date +%s) - $2 )) s)"); say "passed: $1"
}
fail_step() { FAILED+=("$1"); say "FAILED: $1 (log: $OUT)"; }

t=$(date +%s)
say "debootstrap --variant=minbase $SUITE from $MIRROR into $FRESH (a few minutes)"
if ! debootstrap --variant=minbase --cache-dir="$CACHE" "$SUITE" "$FRESH" "$MIRROR" >"$OUT/debootstrap.log" 2>&1; then
  tail -5 "$OUT/debootstrap.log" >&2
  die "debootstrap could not build the root from $MIRROR (log: $OUT/debootstrap.log)"
fi
step "minimal $SUITE root (debootstrap --variant=minbase)" "$t"
mount --bind /dev "$FRESH/dev"
mount --bind /dev/pts "$FRESH/dev/pts"
mount -t proc proc "$FRESH/proc"
cp /etc/resolv.conf "$FRESH/etc/resolv.conf"
printf '#!/bin/sh\nexit 101\n' >"$FRESH/usr/sbin/policy-rc.d"; chmod 755 "$FRESH/usr/sbin/policy-rc.d"

if in_root sh -c 'command -v java || command -v javac || command -v mvn || ls /usr/lib/jvm' >"$OUT/no-java.log" 2>&1; then
  fail_step "the root has no Java or Maven (found: $(tr '\n' ' ' <"$OUT/no-java.log"))"
else
  PASSED+=("no java, javac, mvn or /usr/lib/jvm in the root")
fi

t=$(date +%s)
cp "$DEB" "$FRESH/tmp/"
DEBNAME=$(basename "$DEB")
say "apt-get install ./$DEBNAME in the root (its Depends from $MIRROR)"
if in_root sh -c "apt-get update -q && cd /tmp && apt-get install -y -q ./$DEBNAME" >"$OUT/install.log" 2>&1; then
  step "apt-get install ./$DEBNAME (Depends resolved from the archive; $(grep -c '^Setting up' "$OUT/install.log") packages set up, postinst included)" "$t"
else
  tail -20 "$OUT/install.log" >&2
  fail_step "apt-get install ./$DEBNAME (log: install.log)"
  die "the package did not install; nothing else can be checked"
fi
if [ -s "$FRESH/var/cache/touchline/touchline.jsa" ]; then
  PASSED+=("the postinst made the class-data archive /var/cache/touchline/touchline.jsa ($(du -m "$FRESH/var/cache/touchline/touchline.jsa" | cut -f1) MB)")
else
  fail_step "no class-data archive /var/cache/touchline/touchline.jsa after the install"
fi

t=$(date +%s)
if in_root touchline --version >"$OUT/version.log" 2>&1 && head -1 "$OUT/version.log" | grep -qx "Touchline $VERSION"; then
  step "touchline --version: $(head -1 "$OUT/version.log")" "$t"
else
  fail_step "touchline --version (log: version.log)"
fi

PORT=$(python3 -c 'import socket; s=socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
t=$(date +%s)
"${IN_ROOT[@]}" touchline-robot --id 4 --team 13 --console "127.0.0.1:$PORT" --port 0 >"$OUT/robot.log" 2>&1 &
ROBOT=$!
if in_root touchline record --bind 127.0.0.1 --port "$PORT" --seconds 4 --out /tmp/match.mcap >"$OUT/record.log" 2>&1 \
    && in_root touchline replay --headless /tmp/match.mcap >"$OUT/replay-recording.log" 2>&1 \
    && grep -q ' robot 4 ' "$OUT/replay-recording.log"; then
  step "touchline record of the packaged touchline-robot, replay --headless of it: robot 4 in the recording" "$t"
else
  fail_step "record + replay of the simulated robot (logs: record.log, replay-recording.log)"
fi
kill "$ROBOT" 2>/dev/null || true
wait "$ROBOT" 2>/dev/null || true

t=$(date +%s)
if in_root touchline replay --headless /opt/touchline/lib/app/samples/demo-team.mcap >"$OUT/replay-sample.log" 2>&1 \
    && grep -q 'replayed 9295 envelopes' "$OUT/replay-sample.log"; then
  step "touchline replay --headless of the packaged sample: $(grep -o 'replayed 9295 envelopes' "$OUT/replay-sample.log")" "$t"
else
  fail_step "replay of the packaged sample (log: replay-sample.log)"
fi

t=$(date +%s)
say "installing Xvfb in the root (for this check only)"
if in_root apt-get install -y -q --no-install-recommends xvfb xauth >"$OUT/xvfb-install.log" 2>&1; then
  # a display number free on this machine (Xvfb's abstract socket is shared with the host's network namespace)
  D=90; while [ -e "/tmp/.X$D-lock" ] || [ -e "$FRESH/tmp/.X$D-lock" ]; do D=$((D + 1)); done
  "${IN_ROOT[@]}" Xvfb ":$D" -screen 0 1280x800x24 -nolisten tcp >"$OUT/xvfb.log" 2>&1 &
  XVFB_PID=$!
  EXEC=$(sed -n 's/^Exec=//p' "$FRESH/usr/share/applications/touchline.desktop")
  # --port 0: the console's UDP port 11011 may be held by a console running on this machine (one network)
  "${IN_ROOT[@]}" sh -c "DISPLAY=:$D exec $EXEC --port 0" >"$OUT/window.log" 2>&1 &
  CONSOLE=$!
  # the console's own start mark (touchline.cli.StartMarks) says when the window is shown
  for _ in $(seq 1 600); do
    grep -q 'touchline: window shown' "$OUT/window.log" && break
    kill -0 "$CONSOLE" 2>/dev/null || break
    sleep 0.2 # polling the console's log for its start mark, not synchronisation between our own processes
  done
  if grep -q 'touchline: window shown' "$OUT/window.log"; then
    # the picture once the window is painted: the display is one colour until then (mapped, not yet drawn)
    COLOURS=0
    for _ in $(seq 1 60); do
      import -display ":$D" -window root "$OUT/window.png" 2>"$OUT/screenshot.log" || true
      COLOURS=$(identify -format '%k' "$OUT/window.png" 2>/dev/null || echo 0)
      [ "$COLOURS" -gt 16 ] && break
      sleep 1 # polling the display until the window is drawn, not synchronisation
    done
    step "the desktop entry's command ($EXEC) shows the window on Xvfb: $(grep -o 'window shown.*' "$OUT/window.log" | head -1); screenshot window.png ($COLOURS colours)" "$t"
    [ "$COLOURS" -gt 16 ] || fail_step "the window was not drawn within a minute of being shown (window.png is one colour)"
  else
    fail_step "the desktop entry's command did not show the window within 120 s (log: window.log)"
  fi
  kill "$CONSOLE" 2>/dev/null || true
  wait "$CONSOLE" 2>/dev/null || true
else
  fail_step "could not install xvfb in the root (log: xvfb-install.log)"
fi

COMMIT=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
{
  echo "fresh-Debian check of $DEBNAME, $(date -u '+%Y-%m-%d %H:%M UTC'), commit $COMMIT, $SUITE from $MIRROR, $(( $(date +%s) - T0 )) s in all"
  for p in "${PASSED[@]}"; do echo "passed: $p"; done
  for f in "${FAILED[@]+"${FAILED[@]}"}"; do echo "FAILED: $f"; done
} | tee "$OUT/result.txt"
[ ${#FAILED[@]} -eq 0 ]
