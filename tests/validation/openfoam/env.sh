# Sourced by the OpenFOAM reference scripts (tests/validation/openfoam/*/run.sh): OpenFOAM v1912,
# Debian's package (installed when missing), its environment from etc/bashrc (noisy, and not -u
# clean: the caller sets -u after this).
if ! command -v blockMesh > /dev/null; then
  if [ "$(id -u)" = 0 ]; then apt-get install -y openfoam; else sudo apt-get install -y openfoam; fi
fi
rc=/usr/share/openfoam/etc/bashrc
[ -f "$rc" ] || rc=$(dpkg -L openfoam | grep 'etc/bashrc$' | head -n 1)
source "$rc" > /dev/null 2>&1 || true
