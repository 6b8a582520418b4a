#!/bin/sh
# full_disk.sh <folder> <command...>: runs the command with a 64 KiB file system (tmpfs) on
# <folder>, in a private mount namespace (`unshare -rm`), so that a write there fails with ENOSPC
# as on a full disk. Exit code 77 (ctest's SKIP) where this machine refuses such a namespace; the
# file size limit tests (`ulimit -f`) check a refused write everywhere.
folder=$1
shift
mkdir -p "$folder" || exit 1
small_disk='mount -t tmpfs -o size=64k lamina-full-disk "$1"'
if ! unshare -rm sh -c "$small_disk" sh "$folder" 2>/dev/null; then
  echo "SKIP: no small file system can be mounted here (unshare -rm is refused)"
  exit 77
fi
exec unshare -rm sh -c "$small_disk"' && shift && exec "$@"' sh "$folder" "$@"
