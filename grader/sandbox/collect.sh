#!/bin/sh
# Runs inside the grader's sandbox: collect.sh FILE... -- COMMAND [ARG...]
# Runs COMMAND (without file descriptor 3), then hands each FILE it left in the scratch folder
# back to the grader on descriptor 3, as a line "NAME SIZE" followed by the file's bytes, and
# exits with COMMAND's status (128 + N if signal N ended it).
files=""
while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do
    files="$files $1"
    shift
done
shift
"$@" 3>&-
status=$?
for file in $files; do
    if [ -f "$file" ] && [ ! -L "$file" ]; then
        printf '%s %s\n' "$file" "$(wc -c < "$file")" >&3
        cat "$file" >&3
    fi
done
exit "$status"
