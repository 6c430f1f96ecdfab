# Colours for the scripts' own lines, sourced by ./touchline and packaging/*.sh: only when the
# stream is a terminal and NO_COLOR is not set (https://no-color.org). A pipe, a log file or CI
# gets the plain words, no escape codes.
if [ -t 1 ] && [ -z "${NO_COLOR:-}" ]; then TL_COLOUR_OUT=1; else TL_COLOUR_OUT=; fi
if [ -t 2 ] && [ -z "${NO_COLOR:-}" ]; then TL_COLOUR_ERR=1; else TL_COLOUR_ERR=; fi

# paint out|err SGR TEXT: TEXT in the colour SGR (e.g. '1;34') when that stream is a terminal.
paint() {
  local on=$TL_COLOUR_OUT
  [ "$1" = err ] && on=$TL_COLOUR_ERR
  if [ -n "$on" ]; then printf '\033[%sm%s\033[0m' "$2" "$3"; else printf '%s' "$3"; fi
}
