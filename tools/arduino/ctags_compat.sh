#!/usr/bin/env bash
# Universal Ctags as arduino-cli's sketch preprocessor expects the Arduino
# IDE's ctags (an Exuberant Ctags 5.8 fork) to answer, for the prototypes it
# adds to a sketch's .ino files. Called with that ctags' arguments, the
# preprocessed sketch last. Two differences are bridged:
# - a function's return type: the fork writes `returntype:int` (and
#   `returntype:templateint` for a function template), Universal Ctags
#   `typeref:typename:int` (and a separate `template:<...>` field, asked for
#   here);
# - line numbers: the fork follows the file's `# N "file"` line markers,
#   Universal Ctags 5.9 names the marked file but counts physical lines.
set -o pipefail
src="${!#}"
ctags --fields-c++=+{template} "$@" | awk '
BEGIN { FS = OFS = "\t"; next_line = 1 }
# First file, the source: logical line of every physical line.
FNR == NR {
  if ($0 ~ /^#[ \t]*(line[ \t]+)?[0-9]+([ \t]|$)/) {
    n = $0
    sub(/^#[ \t]*(line[ \t]+)?/, "", n)
    sub(/[^0-9].*$/, "", n)
    map[FNR] = 0
    next_line = n + 0
  } else {
    map[FNR] = next_line++
  }
  next
}
# Then the tags.
{
  code = $0 ~ /\tkind:(function|prototype)(\t|$)/
  tmpl = code && $0 ~ /\ttemplate:/
  out = $1 OFS $2
  for (i = 3; i <= NF; i++) {
    f = $i
    if (f ~ /^template:/) continue
    if (f ~ /^line:[0-9]+$/ && ((n = substr(f, 6) + 0) in map)) f = "line:" map[n]
    else if (code && f ~ /^typeref:typename:/) f = "returntype:" (tmpl ? "template" : "") substr(f, 18)
    out = out OFS f
  }
  print out
}' "$src" -
