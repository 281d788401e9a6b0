#!/usr/bin/env bash
# Installs the Debian 12 packages Prism needs to build, test and render headlessly.
# Idempotent: apt is skipped entirely when every package is already installed.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config python3
  glslang-dev glslang-tools
  # glslc: the reference of tests/shaderc/test_reference_corpus.cpp ("Coming from glslc" in docs/shaderc.md) and of
  # the Vulkan client's tests; the Vulkan client links SPIRV-Tools, whose spirv-val checks its output
  glslc spirv-tools spirv-cross libspirv-cross-c-shared-dev
  libglfw3-dev libglm-dev libimgui-dev
  libosmesa6-dev libegl1-mesa-dev libgl1-mesa-dri libgles-dev
  # prism::vk (docs/vulkan.md): the Vulkan loader and headers, lavapipe (Vulkan on the CPU), the Khronos validation layer
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers
  libpng-dev python3-glad
  libkissfft-dev colord-data
  libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev libfmt-dev nlohmann-json3-dev libxxhash-dev
  libtinyobjloader-dev libstb-dev
  universal-ctags  # scripts/check_function_length.py (tests/architecture)
  xvfb xauth
  lintian  # checks the Debian package cpack builds (tests/integration/installed_runtime.sh)
  clang-14 libclang-rt-14-dev
  clang-format-14  # scripts/check_format.py (tests/format): the format is clang-format 14's
  chromium fonts-dejavu-core  # the browser test tier (tests/report, label browser)
)

missing=()
for pkg in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages present, skipping apt"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
