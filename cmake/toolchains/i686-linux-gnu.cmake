# 32-bit x86 Linux with Debian's cross compiler (g++-i686-linux-gnu) and its multiarch i386
# libraries. Arithmetic in SSE2 registers: the default x87 rounds through 80-bit registers and
# gives other results than every 64-bit build. The programs run natively on an x86-64 kernel with
# IA32 emulation, else under qemu-i386 (tests/cross_arch_hash.sh).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR i686)
set(CMAKE_C_COMPILER i686-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER i686-linux-gnu-g++)
set(CMAKE_C_FLAGS_INIT "-msse2 -mfpmath=sse")
set(CMAKE_CXX_FLAGS_INIT "-msse2 -mfpmath=sse")
