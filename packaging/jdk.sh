# The JDK choice of ./touchline and packaging/package.sh (sourced by both; tested by LauncherJdkTest).
# Versions come from each JDK's `release` file: no JVM is started.

# The newest full JDK (with javac) from MIN to MAX under DIR, or nothing.
newest_jdk() { # [MIN 17] [MAX 25] [DIR /usr/lib/jvm]
  local min=${1:-17} max=${2:-25} d v best="" bestv=0
  for d in "${3:-/usr/lib/jvm}"/*; do
    [ -x "$d/bin/javac" ] && [ -f "$d/release" ] || continue
    v=$(sed -n 's/^JAVA_VERSION="\([0-9][0-9]*\).*/\1/p' "$d/release")
    if [ -n "$v" ] && [ "$v" -ge "$min" ] && [ "$v" -le "$max" ] && [ "$v" -gt "$bestv" ]; then best=$d; bestv=$v; fi
  done
  echo "$best"
}

# The feature version of a java (default: the one on the PATH), 0 if unknown.
java_major() { # [JAVA]
  local j; j=$(readlink -f "${1:-$(command -v java 2>/dev/null)}" 2>/dev/null) || { echo 0; return; }
  sed -n 's/^JAVA_VERSION="\([0-9][0-9]*\).*/\1/p' "$(dirname "$(dirname "$j")")/release" 2>/dev/null | grep . || echo 0
}
