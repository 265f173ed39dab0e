#!/usr/bin/env bash
# Installs every system package perpdot needs to build, test and run its demos,
# from Debian 12's archive only. Safe to re-run: apt-get skips what is present.
# The cross-architecture check (tests/cross_arch_hash.sh) adds Debian's arm64 and i386
# architectures (multiarch libraries for the cross builds) and deb-src entries for the
# Debian mirror already configured (third_party/box2d-deterministic.sh runs `apt-get source box2d`).
set -euo pipefail
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
update=0
for arch in arm64 i386; do
  dpkg --print-foreign-architectures | grep -qx "$arch" || { $SUDO dpkg --add-architecture "$arch"; update=1; }
done
debSrc=/etc/apt/sources.list.d/perpdot-deb-src.sources
if ! grep -rqs "^Types:.*deb-src\|^deb-src " /etc/apt/sources.list /etc/apt/sources.list.d/; then
  # The main archive's URI and suites as the system's deb822 sources name them.
  uri="$(sed -n 's|^URIs: *\(.*/debian\)$|\1|p' /etc/apt/sources.list.d/debian.sources 2>/dev/null | head -n1)"
  suites="$(sed -n 's|^Suites: *\(bookworm.*\)|\1|p' /etc/apt/sources.list.d/debian.sources 2>/dev/null | head -n1)"
  printf 'Types: deb-src\nURIs: %s\nSuites: %s\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    "${uri:-http://deb.debian.org/debian}" "${suites:-bookworm bookworm-updates}" | $SUDO tee "$debSrc" >/dev/null
  update=1
fi
packages=(
  build-essential cmake git pkg-config
  clang clang-tidy libclang-rt-14-dev   # gcc-vs-clang determinism, clang-tidy, libFuzzer
  libbox2d-dev            # collision: b2DynamicTree, b2Collide*, and b2World for cross-checks
  libtbb-dev              # the default workers of a threaded step (WorldDef::workerCount)
  nlohmann-json3-dev      # scene files
  libgtest-dev libgmock-dev libbenchmark-dev
  libsdl2-dev libsdl2-image-dev libimgui-dev   # demo viewer and headless PNG frames
  gnuplot-nox             # cross-check plots
  doxygen                 # API reference (perpdot-docs), warnings fail CI
  xvfb xauth              # windowed viewer test
  dpkg-dev                # apt-get source box2d (third_party/box2d-deterministic.sh)
  g++-aarch64-linux-gnu qemu-user libtbb-dev:arm64 libgtest-dev:arm64   # ARM64 build, run under qemu
  g++-i686-linux-gnu libtbb-dev:i386 libgtest-dev:i386                  # 32-bit x86 build
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} || update)); then
  # A mirror that has not yet synced one architecture's index fails the update but leaves the
  # others usable: the install below then says what it cannot find.
  $SUDO apt-get update || echo "install-deps: apt-get update reported errors; installing with the indexes it has"
fi
if ((${#missing[@]})); then
  echo "install-deps: installing ${missing[*]}"
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi
