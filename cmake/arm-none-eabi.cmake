# SPDX-License-Identifier: MIT
# Cross build for Cortex-M4F with the GNU Arm Embedded toolchain (arm-none-eabi-gcc, newlib):
#   cmake -S . -B build-m4f -DCMAKE_TOOLCHAIN_FILE=cmake/arm-none-eabi.cmake
# The architecture flags are the Makefile's ARCH_m4f-float (cortex-m4, hard float, fpv4-sp-d16).
# The library target cross-builds as is; an executable also needs the application's startup
# code and linker script (see port/cortex-m and linker/ for the QEMU images the tests use).
# For a Cortex-M3 / soft-float build copy this file with ARCH_m3-fixed's flags
# (-mcpu=cortex-m3 -mthumb -mfloat-abi=soft) and configure with -DTINYSUBD_FIXED=ON.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(TINYSUBD_TOOLCHAIN_PREFIX "arm-none-eabi-" CACHE STRING "Cross compiler prefix")
set(CMAKE_C_COMPILER "${TINYSUBD_TOOLCHAIN_PREFIX}gcc")
set(CMAKE_CXX_COMPILER "${TINYSUBD_TOOLCHAIN_PREFIX}g++")
set(CMAKE_ASM_COMPILER "${TINYSUBD_TOOLCHAIN_PREFIX}gcc")
set(CMAKE_AR "${TINYSUBD_TOOLCHAIN_PREFIX}ar" CACHE FILEPATH "Archiver")
set(CMAKE_RANLIB "${TINYSUBD_TOOLCHAIN_PREFIX}ranlib" CACHE FILEPATH "Ranlib")
set(CMAKE_OBJDUMP "${TINYSUBD_TOOLCHAIN_PREFIX}objdump" CACHE FILEPATH "Objdump")

# No startup code or linker script here: test the compiler by building a static library.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(_arch "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
set(CMAKE_C_FLAGS_INIT "${_arch} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${_arch} -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "${_arch}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${_arch} --specs=nano.specs -Wl,--gc-sections")

# Libraries and headers from the target's sysroot only; programs from the host.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
