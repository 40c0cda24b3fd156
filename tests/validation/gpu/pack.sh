#!/bin/sh
# pack.sh: what a lent GPU machine needs to run clsph, into .gpu/ (ignored by git; the device
# tool's `carry`). The machine is bare and fetches nothing: the double and float binaries go
# with every shared library they load but the C library's own (the machine has a newer one),
# compressed (LLVM, which OSMesa loads, is most of it). Run from the repository root after
# building build/ and build-float/; then on the machine tests/validation/gpu/run.sh.
set -eu
for b in build/clsph build-float/clsph; do
  [ -x "$b" ] || { echo "pack.sh: $b is not built" >&2; exit 2; }
done
rm -rf .gpu
mkdir -p .gpu/stage/lib
cp build/clsph .gpu/stage/clsph
cp build-float/clsph .gpu/stage/clsph-float
# the libraries both binaries load, but glibc's (libc, libm, libdl, libpthread, librt, the loader)
for b in build/clsph build-float/clsph; do
  ldd "$b" | awk '$3 ~ /^\// {print $3}'
done | sort -u | while read -r lib; do
  case "$(basename "$lib")" in
  libc.so.* | libm.so.* | libdl.so.* | libpthread.so.* | librt.so.* | ld-linux*) ;;
  *) cp -L "$lib" .gpu/stage/lib/ ;;
  esac
done
tar -C .gpu/stage -cJf .gpu/deps.tar.xz .
rm -rf .gpu/stage
du -h .gpu/deps.tar.xz
