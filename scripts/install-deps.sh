#!/usr/bin/env bash
# Installs the Debian packages dtm needs, only if some are missing (idempotent, quick when done).
# Usage: scripts/install-deps.sh
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config
    libgdal-dev gdal-bin libgeographiclib-dev libvtk9-dev libtbb-dev
    libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev libcgal-dev
    clang libclang-rt-14-dev python3
    libcairo2-dev fonts-dejavu-core poppler-utils
    libexpat1-dev libxml2-utils python3-lxml python3-ezdxf
    python3-scipy strace python3-qgis clang-format
    # test-only oracles (volumes): numpy statistics, QGIS processing algorithms (headless)
    python3-numpy qgis-providers
    # the distributed run's MPI backend (ADR 0008)
    libopenmpi-dev openmpi-bin
)

missing=()
for package in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${db:Status-Status}' "$package" 2>/dev/null || true)
    if [[ "$status" != "installed" ]]; then
        missing+=("$package")
    fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
    echo "install-deps: all ${#packages[@]} packages present"
    exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
    sudo_cmd=(sudo)
fi
"${sudo_cmd[@]}" apt-get update
"${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${missing[@]}"
