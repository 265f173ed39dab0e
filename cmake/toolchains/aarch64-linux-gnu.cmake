# ARM64 Linux with Debian's cross compiler (g++-aarch64-linux-gnu) and its multiarch arm64
# libraries; programs run under qemu-user (tests/cross_arch_hash.sh, gtest discovery).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64)
