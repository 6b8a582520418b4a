#!/bin/sh
# read_only.sh <folder> <command...>: runs the command with <folder> an empty folder it cannot
# write in, made so in the way this machine allows: mode 555 for a user; for root, who writes
# through mode 555, a read-only bind mount of it in a private mount namespace (`unshare -rm`).
# Exit code 77 (ctest's SKIP) when root cannot make such a namespace here; the tests on /sys,
# where not even root creates files, check an unwritable folder then.
folder=$1
shift
rm -rf "$folder" && mkdir -p "$folder" || exit 1
if [ "$(id -u)" != 0 ]; then
  chmod 555 "$folder"
  "$@"
  code=$?
  chmod 755 "$folder"
  exit $code
fi
read_only='mount --bind "$1" "$1" && mount -o remount,ro,bind "$1"'
if ! unshare -rm sh -c "$read_only" sh "$folder" 2>/dev/null; then
  echo "SKIP: running as root, and no read-only mount can be made here (unshare -rm is refused)"
  exit 77
fi
exec unshare -rm sh -c "$read_only"' && shift && exec "$@"' sh "$folder" "$@"
