#!/usr/bin/env bash
# The Vulkan agreement tier (tests/vulkan) on a GPU machine that is not Debian 12 and cannot
# install packages (docs/gpu.md, "Vulkan"): pack the test binaries with the Debian libraries
# they load (OSMesa and its LLVM, lavapipe, the validation layer...) on the build machine, then
# unpack and run them there against three pairings of drivers.
#   scripts/gpu-vulkan-agreement.sh pack BUILD_DIR BUNDLE.tar.xz     (on the build machine)
#   scripts/gpu-vulkan-agreement.sh run BUNDLE.tar.xz OUT_DIR        (in the checkout, on the GPU machine)
# The test binaries name their checkout's absolute paths (goldens, scenes, prism-render); `run`
# recreates those paths as links to the checkout it runs in.
set -uo pipefail
mode=${1:?usage: see the header}
pack() {
  local build=$1 bundle=$2 stage
  stage=$(mktemp -d)
  mkdir -p "$stage"/{bin,lib,fallback,icd,layers}
  cp "$build/tests/vulkan/prism_vulkan_vk_tests" "$build/apps/prism-render" "$build/apps/prism-agreement" "$stage/bin/"
  echo "$(cd "$build/.." && pwd) $(cd "$build" && pwd)" > "$stage/paths"
  local vk=/usr/lib/x86_64-linux-gnu
  # Libraries a GPU machine has in its own (newer) versions are used from there when present.
  local prefer_system='^lib(stdc\+\+|gcc_s|z|zstd|lzma|expat|ffi|X|xcb|bsd|md|drm|wayland|xshmfence|tinfo|GLdispatch|EGL|vulkan\.so|xml2|png16|glfw)'
  for lib in $( (for b in "$stage"/bin/* $vk/libvulkan_lvp.so $vk/libVkLayer_khronos_validation.so; do ldd "$b"; done) |
                awk '$3 ~ /^\// {print $3}' | sort -u | grep -vE '/(libc|libm|libpthread|libdl|librt|ld-linux-x86-64)\.so'); do
    if basename "$lib" | grep -qE "$prefer_system"; then cp -L "$lib" "$stage/fallback/"; else cp -L "$lib" "$stage/lib/"; fi
  done
  cp -L $vk/libvulkan_lvp.so $vk/libVkLayer_khronos_validation.so "$stage/lib/"
  sed 's#"library_path": *"[^"]*"#"library_path": "libvulkan_lvp.so"#' /usr/share/vulkan/icd.d/lvp_icd.x86_64.json > "$stage/icd/lvp.json"
  sed 's#"library_path": *"[^"]*"#"library_path": "libVkLayer_khronos_validation.so"#' \
    /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json > "$stage/layers/VkLayer_khronos_validation.json"
  tar -C "$stage" -cf - . | xz -9 -T0 > "$bundle" && rm -rf "$stage" && ls -la "$bundle"
}
run() {
  local bundle=$1 out=$2 g checkout=$PWD
  g=$(mktemp -d) && mkdir -p "$out" && tar -xJf "$bundle" -C "$g"
  for f in "$g"/fallback/*; do ldconfig -p | awk '{print $1}' | grep -qx "$(basename "$f")" || cp "$f" "$g/lib/"; done
  read -r src build < "$g/paths"
  mkdir -p "$build/apps" "$build/tests/vulkan" && cp "$g/bin/prism-render" "$build/apps/"
  for d in examples tests; do [ -e "$src/$d" ] || ln -s "$checkout/$d" "$src/$d"; done
  export LD_LIBRARY_PATH=$g/lib VK_LAYER_PATH=$g/layers PRISM_VULKAN_REPORT=1
  local nv egl=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json status=0
  nv=$(ls /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json /usr/share/vulkan/icd.d/nvidia_icd.json 2>/dev/null | head -1)
  tier() {  # name, then the environment of the run
    local name=$1; shift
    env "$@" "$g/bin/prism_vulkan_vk_tests" > "$out/$name.txt" 2>&1 || status=1
    echo "=== $name ($*): $(grep -E '^\[  (PASSED|FAILED)  \] [0-9]' "$out/$name.txt" | tr '\n' ' ')"
    if [ -d "$build/tests/vulkan/out" ]; then  # the tier's images: the CLI renders, and a failing case's Vulkan and difference images
      tar -C "$build/tests/vulkan" -czf "$out/$name.failures.tgz" out && rm -rf "$build/tests/vulkan/out"
    fi
  }
  tier lavapipe_vs_llvmpipe VK_DRIVER_FILES="$g/icd/lvp.json" PRISM_GL_BACKEND=osmesa
  tier gpu_vulkan_vs_llvmpipe VK_DRIVER_FILES="$nv" PRISM_GL_BACKEND=osmesa
  tier gpu_vulkan_vs_gpu_gl VK_DRIVER_FILES="$nv" PRISM_GL_BACKEND=egl PRISM_EGL_PLATFORM=device __EGL_VENDOR_LIBRARY_FILENAMES=$egl
  (cd "$out" && VK_DRIVER_FILES="$nv" PRISM_GL_BACKEND=osmesa "$g/bin/prism-agreement" --out agreement --size 256 > agreement.txt 2>&1) || status=1
  VK_DRIVER_FILES="$nv" "$g/bin/prism-render" --backend vulkan --shader phong --mesh torus --size 1024x1024 --out "$out/gpu_phong_torus_1024.png"
  return $status
}
case "$mode" in
  pack) pack "${2:?BUILD_DIR}" "${3:?BUNDLE.tar.xz}" ;;
  run) run "${2:?BUNDLE.tar.xz}" "${3:?OUT_DIR}" ;;
  *) echo "gpu-vulkan-agreement.sh: unknown mode '$mode' (pack or run)" >&2; exit 2 ;;
esac
