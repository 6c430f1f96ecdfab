#!/usr/bin/env bash
# ./touchline package [--platform linux|win|mac]: Touchline as a desktop application (docs/install.md).
#
#   linux (default)  target/package/touchline_<version>_amd64.deb   desktop entry, icon, `touchline` on the PATH,
#                                                                  its own jlinked Java runtime (no JDK, no Maven)
#                    target/package/touchline-<version>-linux-x64.tar.gz   the same app image to unpack anywhere
#   win | mac        target/package/touchline-<version>-<platform>.zip|.tar.gz   the console's jars with that
#                    platform's JavaFX (Maven classifier) and a start script (touchline.cmd / touchline);
#                    built here, not run here: the user's Java 17+ runs it.
#
# The launcher (./touchline) has already built the console (target/classes, the jar) and the robot side.
# The jlinked runtime is cached in target/package/runtime-<key>/ and reused while the JDK and the module
# list stay the same.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
. "$ROOT/packaging/colour.sh"
say() { printf '%s %s\n' "$(paint err '1;34' '[touchline package]')" "$*" >&2; }
die() { printf '%s %s\n' "$(paint err '1;31' '[touchline package]')" "$*" >&2; exit 1; }

PLATFORM=linux
while [ $# -gt 0 ]; do
  case "$1" in
    --platform) PLATFORM=${2:-}; shift 2 ;;
    --platform=*) PLATFORM=${1#*=}; shift ;;
    *) die "unknown option $1 (use --platform linux|win|mac)" ;;
  esac
done
case "$PLATFORM" in linux|win|mac) ;; *) die "unknown platform '$PLATFORM' (linux, win or mac)" ;; esac

VERSION=$(sed -n 's/^version=//p' target/classes/touchline/version.properties 2>/dev/null || true)
[ -n "$VERSION" ] || die "target/classes/touchline/version.properties missing: build the console first (./touchline build)"
[ -f CHANGELOG.md ] || die "CHANGELOG.md missing"
OUT=target/package
BIN="${TOUCHLINE_ROBOTSIDE_BIN:-$ROOT/robot-side/build/bin}"
mkdir -p "$OUT"

# The product's jars: runtime scope. -Djavafx.platform picks the JavaFX classifier jars.
copy_jars() { # dir javafx-platform
  rm -rf "$1"; mkdir -p "$1"
  mvn -q -B -ntp ${TOUCHLINE_MVN_OFFLINE:+-o} dependency:copy-dependencies -DincludeScope=runtime \
    -DoutputDirectory="$1" -Djavafx.platform="$2"
  # the console's own jar, from target/classes (the package test runs before Maven's package phase)
  jar --create --file "$1/touchline-$VERSION.jar" -C target/classes .
}

if [ "$PLATFORM" != linux ]; then
  NAME="touchline-$VERSION-$PLATFORM"
  STAGE="$OUT/$NAME"
  say "assembling the $PLATFORM app layout (JavaFX classifier '$PLATFORM') in $STAGE"
  rm -rf "$STAGE"; mkdir -p "$STAGE"
  copy_jars "$STAGE/lib" "$PLATFORM"
  # only this platform's JavaFX natives: drop the Linux classifier jars a Linux build resolves as well
  find "$STAGE/lib" -name 'javafx-*-linux.jar' -delete
  ls "$STAGE/lib"/javafx-graphics-*-"$PLATFORM".jar >/dev/null 2>&1 || die "no javafx-graphics jar for '$PLATFORM' was resolved"
  cp README.md CHANGELOG.md "$STAGE/"
  cp -r samples "$STAGE/samples"
  if [ "$PLATFORM" = win ]; then
    # CRLF line ends for cmd.exe
    sed 's/$/\r/' packaging/windows/touchline.cmd >"$STAGE/touchline.cmd"
    rm -f "$OUT/$NAME.zip"
    (cd "$OUT" && python3 -m zipfile -c "$NAME.zip" "$NAME")
    say "done: $OUT/$NAME.zip (unzip, then touchline.cmd console; needs Java 17+ on the PATH)"
  else
    install -m 755 packaging/mac/touchline "$STAGE/touchline"
    tar -C "$OUT" -czf "$OUT/$NAME.tar.gz" "$NAME"
    say "done: $OUT/$NAME.tar.gz (unpack, then ./touchline console; needs Java 17+)"
  fi
  exit 0
fi

# The package's runtime: JDK 17's where one is installed. JDK 25's (what the launcher builds and runs with
# when installed) is 13 MB larger and takes the package to 129 MB, over its 120 MB budget (docs/benchmarks.md,
# "Seventeenth session"); otherwise the JDK on the PATH. TOUCHLINE_PACKAGE_JAVA_HOME chooses another.
. packaging/jdk.sh
PACKAGE_JDK=${TOUCHLINE_PACKAGE_JAVA_HOME:-$(newest_jdk 17 17)}
if [ -n "$PACKAGE_JDK" ]; then PATH="$PACKAGE_JDK/bin:$PATH"; fi
say "the package's Java runtime: $(java -version 2>&1 | head -1)"
command -v jpackage >/dev/null || die "jpackage missing: it comes with the JDK (openjdk-17-jdk-headless)"
for t in fakeroot dpkg-deb; do command -v "$t" >/dev/null || die "$t missing (./touchline package installs it)"; done
for b in touchline-robot touchline-nao-sim; do
  [ -x "$BIN/$b" ] || die "$BIN/$b missing: build the robot side first (./touchline build)"
done

START=$(date +%s)
STAGE="$OUT/input"
say "collecting the console's jars (Linux JavaFX) in $STAGE"
copy_jars "$STAGE" linux
# zstd-jni and lz4-java carry their natives for every platform (7 MB): the package keeps Linux x86-64's
python3 - "$STAGE"/zstd-jni-*.jar "$STAGE"/lz4-java-*.jar <<'PY'
import re, shutil, sys, zipfile
other = re.compile(r'^(net/jpountz/util/)?(aix|darwin|freebsd|win|linux/(?!amd64/))[^/]*/.*[.](so|dll|dylib|jnilib)$')
for jar in sys.argv[1:]:
    with zipfile.ZipFile(jar) as src, zipfile.ZipFile(jar + '.tmp', 'w', zipfile.ZIP_DEFLATED) as dst:
        for e in src.infolist():
            if not other.match(e.filename):
                dst.writestr(e, src.read(e.filename))
    shutil.move(jar + '.tmp', jar)
PY
# JavaFX loads its natives from the folder of its jar when they are there, and otherwise extracts them into
# ~/.openjfx/cache (the first start of each user) and compares them with the jar's at every start
python3 - "$STAGE" "$STAGE"/javafx-graphics-*-linux.jar <<'PY'
import os, sys, zipfile
with zipfile.ZipFile(sys.argv[2]) as jar:
    for e in jar.infolist():
        if e.filename.endswith('.so') and '/' not in e.filename:
            with open(os.path.join(sys.argv[1], e.filename), 'wb') as out:
                out.write(jar.read(e))
PY
# the simulated team and NAO come with the package where they run (Linux x86-64)
mkdir -p "$STAGE/robot-side"
install -m 755 -s "$BIN/touchline-robot" "$BIN/touchline-nao-sim" "$STAGE/robot-side/"
cp -r samples "$STAGE/samples"

# A trimmed Java runtime: only the modules the console and its libraries use (the class path is not
# modular, so the list is fixed here and checked by the package test: a missing module fails there).
MODULES=java.base,java.desktop,java.logging,java.management,java.naming,java.net.http,java.scripting,java.sql,java.xml,jdk.crypto.ec,jdk.jfr,jdk.unsupported,jdk.unsupported.desktop,jdk.zipfs,jdk.charsets
KEY=$( { java -version 2>&1; echo "$MODULES"; } | sha1sum | cut -c1-12)
RUNTIME="$OUT/runtime-$KEY"
if [ ! -x "$RUNTIME/bin/java" ]; then
  say "linking a trimmed Java runtime (jlink) into $RUNTIME"
  rm -rf "$OUT"/runtime-*
  jlink --add-modules "$MODULES" --strip-debug --no-man-pages --no-header-files --compress=2 \
    --generate-cds-archive --output "$RUNTIME"
else
  say "reusing the Java runtime in $RUNTIME"
fi

# From JDK 24 the runtime warns at start about native libraries and sun.misc.Unsafe: allowed (as ./touchline does)
QUIET_JDK24=()
if [ "$(java_major "$RUNTIME/bin/java")" -ge 24 ]; then
  QUIET_JDK24=(--java-options '--enable-native-access=ALL-UNNAMED' --java-options '--sun-misc-unsafe-memory-access=allow')
fi

IMAGE="$OUT/image"
rm -rf "$IMAGE"
say "building the app image (jpackage)"
# $APPDIR is the installed lib/app directory (jpackage expands it in the launcher's configuration)
jpackage --type app-image --name touchline --dest "$IMAGE" --input "$STAGE" \
  --main-jar "touchline-$VERSION.jar" --main-class touchline.cli.Main --runtime-image "$RUNTIME" \
  --app-version "$VERSION" --vendor "Touchline" --icon packaging/linux/touchline.png \
  --description "Pitch-side debug console for RoboCup robot teams" \
  --java-options '-XX:+UseZGC' --java-options '-Dtouchline.robotside.bin=$APPDIR/robot-side' "${QUIET_JDK24[@]}"
chmod 755 "$IMAGE/touchline/lib/app/robot-side/"*
cp CHANGELOG.md "$IMAGE/touchline/"

# The launcher runs ZGC, which has no compressed pointers: the JVM maps the runtime's
# classes_nocoops.jsa (the JDK's class-data archive) and never classes.jsa, 12 MB the package need
# not carry. The runtime's native libraries lose their symbols (libjvm.so 24 -> 20 MB).
rm -f "$IMAGE/touchline/lib/runtime/lib/server/classes.jsa"
chmod -R u+w "$IMAGE/touchline/lib/runtime"
find "$IMAGE/touchline/lib/runtime" -name '*.so' -exec strip --strip-unneeded {} +

# The classes a console start loads, for the installed console's class-data archive (AppCDS; docs/install.md):
# a training run of the image's runtime opens the window on a private Xvfb display with the demo layout,
# draws 120 frames and closes, and the JVM writes the names of the classes it loaded. The archive itself is
# made where the package is installed (its postinst, lib/touchline-class-archive): JDK 17 ties an archive to
# the class path as written when it was made, so one made here (target/package/image/…) is ignored under
# /opt/touchline (measured, docs/benchmarks.md "Desktop entry to window").
command -v xvfb-run >/dev/null || die "xvfb-run missing (package xvfb): the class list is recorded with the window open"
APP_DIR="$ROOT/$IMAGE/touchline/lib/app"
CLASSPATH_OF_APP=$(sed -n "s|^app.classpath=[$]APPDIR|$APP_DIR|p" "$APP_DIR/touchline.cfg" | paste -sd: -)
TRAINING=$(mktemp -d)
say "recording the classes a console start loads (a training run under Xvfb, about 10 s on a quiet machine)"
if ! timeout 300 xvfb-run -a "$IMAGE/touchline/lib/runtime/bin/java" -XX:+UseZGC \
    -XX:DumpLoadedClassList="$APP_DIR/touchline.classlist" -Dtouchline.cds.training=120 \
    -Dtouchline.robotside.bin="$APP_DIR/robot-side" -cp "$CLASSPATH_OF_APP" touchline.cli.Main \
    console --port 0 --demo --layouts "$TRAINING" >"$TRAINING/training.log" 2>&1 \
    || [ "$(wc -l <"$APP_DIR/touchline.classlist")" -lt 1000 ]; then
  tail -5 "$TRAINING/training.log" >&2
  die "the training run for the class list failed (above)"
fi
rm -rf "$TRAINING"

TARBALL="$OUT/touchline-$VERSION-linux-x64.tar.gz"
say "writing $TARBALL"
tar -C "$IMAGE" -czf "$TARBALL" touchline

# The .deb: the app image under /opt/touchline, the command on the PATH, the desktop entry and the
# icon as plain files of the package (the postinst only makes the class-data archive, the postrm removes
# it: `dpkg -x` into a scratch root gives a console that works, only starts slower). Written with
# dpkg-deb directly: jpackage --type deb took 7 minutes here (it compresses with xz and asks dpkg about
# every native library) and left the PATH to a postinst.
say "building the Debian package"
TREE="$OUT/deb-tree"
rm -rf "$TREE"
mkdir -p "$TREE/DEBIAN" "$TREE/opt" "$TREE/usr/bin" "$TREE/usr/share/applications" \
  "$TREE/usr/share/icons/hicolor/256x256/apps" "$TREE/usr/share/doc/touchline"
cp -a "$IMAGE/touchline" "$TREE/opt/touchline"
# The .deb's console maps the class-data archive its postinst makes in /var/cache/touchline (the
# .tar.gz's does not: it has no install step). The archive holds the JDK's classes too, so the deb
# leaves out the runtime's own (10 MB, used only where the archive is missing: then the start is slower).
install -m 755 packaging/linux/touchline-class-archive "$TREE/opt/touchline/lib/touchline-class-archive"
install -m 755 packaging/linux/postinst packaging/linux/postrm "$TREE/DEBIAN/"
printf '%s\n' 'java-options=-XX:SharedArchiveFile=/var/cache/touchline/touchline.jsa' 'java-options=-Xshare:auto' \
  'java-options=-Xlog:cds=off' 'java-options=-Xlog:cds+dynamic=off' >>"$TREE/opt/touchline/lib/app/touchline.cfg"
rm -f "$TREE/opt/touchline/lib/runtime/lib/server/classes_nocoops.jsa"
ln -s /opt/touchline/bin/touchline "$TREE/usr/bin/touchline"
ln -s /opt/touchline/lib/app/robot-side/touchline-robot "$TREE/usr/bin/touchline-robot"
ln -s /opt/touchline/lib/app/robot-side/touchline-nao-sim "$TREE/usr/bin/touchline-nao-sim"
install -m 644 packaging/linux/touchline.desktop "$TREE/usr/share/applications/touchline.desktop"
install -m 644 packaging/linux/touchline.png "$TREE/usr/share/icons/hicolor/256x256/apps/touchline.png"
install -m 644 CHANGELOG.md "$TREE/usr/share/doc/touchline/CHANGELOG.md"
SIZE_KB=$(du -sk "$TREE" | cut -f1)
# JavaFX's natives (inside its jars) need GTK 3 and OpenGL; the Java runtime X11, fonts and zlib;
# the robot side ZeroMQ, protobuf and TurboJPEG.
cat >"$TREE/DEBIAN/control" <<EOF
Package: touchline
Version: $VERSION
Section: devel
Priority: optional
Architecture: amd64
Maintainer: Touchline <touchline@localhost>
Installed-Size: $SIZE_KB
Depends: libc6, zlib1g, libstdc++6, libgtk-3-0, libgl1, libx11-6, libxext6, libxi6, libxrender1, libxtst6, libxxf86vm1, libfreetype6, libfontconfig1, libzmq5, libprotobuf32, libturbojpeg0
Recommends: libgl1-mesa-dri, fonts-dejavu-core
Description: Pitch-side debug console for RoboCup robot teams
 Watch every robot of a team during a match, toggle debug outputs, record and
 replay sessions, referee a practice game with the embedded GameController and
 drive NAO robots. Carries its own trimmed Java runtime; the simulated robot
 (touchline-robot) and NAO (touchline-nao-sim) come with it.
EOF
DEB="$OUT/touchline_${VERSION}_amd64.deb"
rm -f "$DEB"
fakeroot dpkg-deb -Zgzip -z6 -b "$TREE" "$DEB" >/dev/null
rm -rf "$TREE"
say "done in $(( $(date +%s) - START )) s: $DEB ($(du -h "$DEB" | cut -f1), installed $((SIZE_KB / 1024)) MB), $TARBALL"
