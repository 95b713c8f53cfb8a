# SPDX-License-Identifier: MIT
# tinysubd — every entry point. See README.md.
#   make test-host  the quick loop: host float/fixed tests only (no QEMU)
#   make test-long  host float/fixed tests with the long variants (deepest levels; not in make test)
#   make test    everything a change must pass: host float/fixed tests with ASan+UBSan, the
#                same tests under QEMU on Cortex-M4F (float) and Cortex-M3 (Q16.16), host =
#                QEMU output hashes, link-time proofs, harness self-tests, the subd tool test.
#                Installs the ARM toolchain and QEMU from Debian packages when missing.
#   make demo    firmware demo in QEMU + host tool on bundled meshes -> build/demo/
#   make bench   performance report (never part of make test)
#   make bench-peers  the same Loop / Doo-Sabin work by OpenSubdiv, CGAL and OpenMesh
#   make tool    build/bin/subd (float32) and build/bin/subd-fixed (Q16.16)
#   make compare-ref REF=<commit>  the tool's outputs byte for byte against those of <commit>
#   make amalgamate  dist/tinysubd.c + dist/tinysubd.h: the library as one file (README)

.SUFFIXES:
.DELETE_ON_ERROR:
B := build
SHARED ?= ../shared

SRC      := $(sort $(wildcard src/*.c))
TEST_SRC := $(sort $(wildcard test/test_*.c)) test/harness.c test/fixtures.c test/loop_limit_ref.c test/loop_cmp.c
GEN      := $(B)/gen/corpus.h $(B)/gen/readme_example.c $(B)/gen/suites.h

WARN := -std=c99 -Wall -Wextra -Werror -pedantic -Wshadow -Wvla -Wdouble-promotion \
        -Wstrict-prototypes -Wmissing-prototypes -ffp-contract=off
SRC_WARN := -Wconversion -Wsign-conversion
INC := -Iinclude -Itest -Iport -I$(B)/gen
# Every object also writes its header dependencies (X.d next to X.o, included at the end), so a
# header change rebuilds exactly what includes it; generated headers are built first (| $(GEN)).
# Objects also depend on this Makefile, which holds their flags.
DEP := -MMD -MP
MK  := Makefile

# ------------------------------------------------------------------ host variants
HOST_CC ?= gcc
SAN     := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
HOST_FLAGS_host-float := -DSUBD_HOST=1 -DSUBD_FIXED=0 -O1 -g $(SAN)
HOST_FLAGS_host-fixed := -DSUBD_HOST=1 -DSUBD_FIXED=1 -O1 -g $(SAN)
HOST_FLAGS_tool-float := -DSUBD_HOST=1 -DSUBD_FIXED=0 -O2 -g
HOST_FLAGS_tool-fixed := -DSUBD_HOST=1 -DSUBD_FIXED=1 -O2 -g
HOST_FLAGS_bench-float := -DSUBD_HOST=1 -DSUBD_FIXED=0 -O2
# host-gnu: the library and the host tests built as an integrator might: gcc's default
# -std=gnu11 (which means -ffp-contract=fast), no -ffp-contract=off, and FMA instructions
# available (-march=haswell on x86). Its hashes must equal host-float's (src/fp_contract.h).
GNU_WARN := -std=gnu11 -Wall -Wextra -Werror -Wshadow -Wvla -Wdouble-promotion -Wstrict-prototypes \
            -Wmissing-prototypes
GNU_MARCH := $(if $(filter x86_64 i686 i386,$(shell uname -m)),-march=haswell,)
WARN_host-gnu := $(GNU_WARN)
HOST_FLAGS_host-gnu := -DSUBD_HOST=1 -DSUBD_FIXED=0 -O2 $(GNU_MARCH)
# Runs host-gnu's tests only where the CPU can execute them.
GNU_RUNS := [ -z "$(GNU_MARCH)" ] || { grep -qw avx2 /proc/cpuinfo && grep -qw fma /proc/cpuinfo; } 2>/dev/null
HOST_TEST_PORT := port/host/test_port.c port/print.c port/host/png.c port/host/render.c port/host/render_text.c
TOOL_PORT      := port/host/subd_main.c port/host/tool_error.c port/host/tool_parse.c port/host/subd_options.c port/host/subd_commands.c port/host/cmd_loop.c port/host/cmd_pia.c port/host/cmd_quasi48.c port/host/cmd_alpha.c port/host/cmd_sr48.c port/host/subd_info.c port/host/subd_write.c port/host/subd_stream.c port/host/progress.c port/host/fileio.c port/host/png.c port/host/render.c port/host/render_text.c

define host_variant
$(B)/$(1)/src/%.o: src/%.c $(MK) | dirs
	$(HOST_CC) $(if $(WARN_$(1)),$(WARN_$(1)),$(WARN)) $(SRC_WARN) $(INC) $(DEP) $(HOST_FLAGS_$(1)) -c $$< -o $$@
$(B)/$(1)/test/%.o: test/%.c $(MK) | dirs $(GEN)
	$(HOST_CC) $(if $(WARN_$(1)),$(WARN_$(1)),$(WARN)) $(INC) $(DEP) $(HOST_FLAGS_$(1)) -c $$< -o $$@
$(B)/$(1)/port/%.o: port/%.c $(MK) | dirs
	$(HOST_CC) $(if $(WARN_$(1)),$(WARN_$(1)),$(WARN)) $(INC) -Iport/host $(DEP) $(HOST_FLAGS_$(1)) -c $$< -o $$@
$(B)/$(1)/bench/%.o: bench/%.c $(MK) | dirs
	$(HOST_CC) $(if $(WARN_$(1)),$(WARN_$(1)),$(WARN)) $(INC) -Iport/host $(DEP) $(HOST_FLAGS_$(1)) -c $$< -o $$@
$(B)/$(1)/gen/%.o: $(B)/gen/%.c $(MK) | dirs $(GEN)
	$(HOST_CC) $(if $(WARN_$(1)),$(WARN_$(1)),$(WARN)) $(INC) $(DEP) $(HOST_FLAGS_$(1)) -c $$< -o $$@
$(B)/$(1)/test-fail.o: test/test_harness.c $(MK) | dirs $(GEN)
	$(HOST_CC) $(if $(WARN_$(1)),$(WARN_$(1)),$(WARN)) $(INC) $(DEP) $(HOST_FLAGS_$(1)) -DH_INJECT_FAILURE=1 -c $$< -o $$@
endef
HOST_VARIANTS := host-float host-fixed tool-float tool-fixed bench-float host-gnu
$(foreach v,$(HOST_VARIANTS),$(eval $(call host_variant,$(v))))

host_test_objs = $(SRC:%.c=$(B)/$(1)/%.o) $(TEST_SRC:%.c=$(B)/$(1)/%.o) \
                 $(HOST_TEST_PORT:%.c=$(B)/$(1)/%.o) $(B)/$(1)/gen/corpus.o
$(B)/host-float/test.elf: $(call host_test_objs,host-float)
	$(HOST_CC) $(SAN) $^ -lm -o $@
$(B)/host-fixed/test.elf: $(call host_test_objs,host-fixed)
	$(HOST_CC) $(SAN) $^ -lm -o $@
$(B)/host-gnu/test.elf: $(call host_test_objs,host-gnu)
	$(HOST_CC) $^ -lm -o $@
$(B)/bin/subd: $(SRC:%.c=$(B)/tool-float/%.o) $(TOOL_PORT:%.c=$(B)/tool-float/%.o)
	$(HOST_CC) $^ -lm -o $@
$(B)/bin/subd-fixed: $(SRC:%.c=$(B)/tool-fixed/%.o) $(TOOL_PORT:%.c=$(B)/tool-fixed/%.o)
	$(HOST_CC) $^ -lm -o $@
tool: $(B)/bin/subd $(B)/bin/subd-fixed
# The benchmark: the library, bench/*.c and the file reader at -O2 (variant bench-float).
BENCH_SRC := $(wildcard bench/*.c)
$(B)/bench/bench: $(BENCH_SRC:%.c=$(B)/bench-float/%.o) $(SRC:%.c=$(B)/bench-float/%.o) $(B)/bench-float/port/host/fileio.o
	$(HOST_CC) $^ -lm -o $@

# ------------------------------------------------------------------ Cortex-M variants
CM_CC   := arm-none-eabi-gcc
CM_AR   := arm-none-eabi-ar
CM_NM   := arm-none-eabi-nm
CM_SIZE := arm-none-eabi-size
CM_OBJDUMP := arm-none-eabi-objdump
# Stack use per function is bounded at compile time (-Wstack-usage) on the device.
CM_FLAGS := $(WARN) -O2 -g -ffunction-sections -fdata-sections -fstack-usage -Wstack-usage=1024
ARCH_m4f-float  := -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard
ARCH_m3-fixed   := -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
FIXED_m4f-float := 0
FIXED_m3-fixed  := 1
LDS_m4f-float   := linker/mps2_an386.ld
LDS_m3-fixed    := linker/mps2_an385.ld
MACHINE_m4f-float := mps2-an386
MACHINE_m3-fixed  := mps2-an385
CM_PORT := port/cortex-m/startup.c port/cortex-m/port_cm.c port/print.c

define cm_variant
CMF_$(1) := $(ARCH_$(1)) $(CM_FLAGS) -DSUBD_FIXED=$(FIXED_$(1)) $(INC) -Iport/cortex-m $(DEP)
$(B)/$(1)/src/%.o: src/%.c $(MK) | dirs
	$(CM_CC) $$(CMF_$(1)) $(SRC_WARN) -c $$< -o $$@
$(B)/$(1)/test/%.o: test/%.c $(MK) | dirs $(GEN)
	$(CM_CC) $$(CMF_$(1)) -c $$< -o $$@
$(B)/$(1)/port/%.o: port/%.c $(MK) | dirs
	$(CM_CC) $$(CMF_$(1)) -c $$< -o $$@
$(B)/$(1)/gen/%.o: $(B)/gen/%.c $(MK) | dirs $(GEN)
	$(CM_CC) $$(CMF_$(1)) -c $$< -o $$@
$(B)/$(1)/test-fail.o: test/test_harness.c $(MK) | dirs $(GEN)
	$(CM_CC) $$(CMF_$(1)) -DH_INJECT_FAILURE=1 -c $$< -o $$@
$(B)/$(1)/selftest%.o: test/selftest.c $(MK) | dirs
	$(CM_CC) $$(CMF_$(1)) -DSELFTEST_MODE=$$* -c $$< -o $$@
$(B)/$(1)/libsubd.a: $(SRC:%.c=$(B)/$(1)/%.o)
	rm -f $$@ && $(CM_AR) rcs $$@ $$^
CM_LINK_$(1) = $(CM_CC) $(ARCH_$(1)) -nostartfiles --specs=nano.specs -Wl,--gc-sections \
               -Wl,--fatal-warnings -T $(LDS_$(1)) -Wl,-Map=$$@.map
$(B)/$(1)/test.elf: $(CM_PORT:%.c=$(B)/$(1)/%.o) $(TEST_SRC:%.c=$(B)/$(1)/%.o) $(B)/$(1)/gen/corpus.o $(B)/$(1)/libsubd.a
	$$(CM_LINK_$(1)) $$^ -o $$@
$(B)/$(1)/test-fail.elf: $(CM_PORT:%.c=$(B)/$(1)/%.o) $(B)/$(1)/test-fail.o \
        $(filter-out $(B)/$(1)/test/test_harness.o,$(TEST_SRC:%.c=$(B)/$(1)/%.o)) $(B)/$(1)/gen/corpus.o $(B)/$(1)/libsubd.a
	$$(CM_LINK_$(1)) $$^ -o $$@
$(B)/$(1)/selftest%.elf: $(CM_PORT:%.c=$(B)/$(1)/%.o) $(B)/$(1)/selftest%.o
	$$(CM_LINK_$(1)) $$^ -o $$@
$(B)/$(1)/demo.elf: $(CM_PORT:%.c=$(B)/$(1)/%.o) $(B)/$(1)/port/cortex-m/demo.o $(B)/$(1)/port/cortex-m/demo_pipe.o $(B)/$(1)/libsubd.a
	$$(CM_LINK_$(1)) $$^ -o $$@
# The 4-8 chordal stream step of the demo reads test/data/icosahedron.obj from the corpus.
$(B)/$(1)/demo.elf: $(B)/$(1)/port/cortex-m/demo_sr48.o $(B)/$(1)/gen/corpus.o
$(B)/$(1)/port/cortex-m/demo_sr48.o: | $(B)/gen/corpus.h
# Kept (not deleted as intermediates), so a build with nothing changed does nothing.
.SECONDARY: $(foreach n,0 1 2 3,$(B)/$(1)/selftest$(n).o)
$(1)-images: $(B)/$(1)/test.elf $(B)/$(1)/test-fail.elf $(foreach n,0 1 2 3,$(B)/$(1)/selftest$(n).elf)
endef
$(foreach v,m4f-float m3-fixed,$(eval $(call cm_variant,$(v))))

# m4f-gnu: the M4F library as an integrator might build it (-std=gnu11 -O2, no
# -ffp-contract=off); test/scripts/contract_proofs.sh requires zero fused multiply-adds in it.
$(B)/m4f-gnu/src/%.o: src/%.c $(MK) | dirs
	$(CM_CC) $(ARCH_m4f-float) $(GNU_WARN) $(SRC_WARN) -O2 -DSUBD_FIXED=0 $(INC) $(DEP) -c $< -o $@
$(B)/m4f-gnu/libsubd.a: $(SRC:%.c=$(B)/m4f-gnu/%.o)
	rm -f $@ && $(CM_AR) rcs $@ $^

$(B)/host-float/test-fail.elf: $(filter-out $(B)/host-float/test/test_harness.o,$(call host_test_objs,host-float)) $(B)/host-float/test-fail.o
	$(HOST_CC) $(SAN) $^ -lm -o $@

# ------------------------------------------------------------------ generated sources
# Test inputs (test/data, test/bad) are embedded as C arrays so the same bytes reach QEMU.
CORPUS := $(sort $(wildcard test/data/*) $(wildcard test/bad/*))
$(B)/gen/embed: test/tools/embed.c | dirs
	$(HOST_CC) -std=c99 -O1 -Wall -Werror $< -o $@
$(B)/gen/corpus.c $(B)/gen/corpus.h &: $(B)/gen/embed $(CORPUS)
	$(B)/gen/embed $(B)/gen/corpus.c $(B)/gen/corpus.h $(CORPUS)
# The suite list, derived: every `const test_case suite_NAME[]` of test/test_*.c, in file name
# order, each once (a table defined in both branches of an #if counts once; test/harness.c
# runs them in this order; a new test file needs no registration).
$(B)/gen/suites.h: $(TEST_SRC) $(MK) | dirs
	{ echo '/* SPDX-License-Identifier: MIT */'; echo '/* Generated by the Makefile from test/test_*.c. */'; \
	  sed -n 's/^const test_case \(suite_[a-z0-9_]*\)\[\] = {$$/SUITE(\1)/p' $(sort $(wildcard test/test_*.c)) | awk '!seen[$$0]++'; } > $@.tmp
	@grep -q SUITE $@.tmp || { echo "no test suites found" >&2; exit 1; }
	mv $@.tmp $@
# The README's embedding example is compiled and run by the tests (test/test_embed.c).
$(B)/gen/readme_example.c: README.md | dirs
	awk '/^<!-- embed-example/{f=1;next} f&&/^```c/{g=1;next} g&&/^```/{exit} g{print}' $< > $@
	@test -s $@ || { echo "README.md: embed-example block not found" >&2; exit 1; }

VARIANTS := $(HOST_VARIANTS) m4f-float m3-fixed m4f-gnu
dirs:
	@mkdir -p $(B)/gen $(B)/bin $(B)/logs $(B)/bench $(foreach v,$(VARIANTS),$(B)/$(v)/src $(B)/$(v)/test \
	    $(B)/$(v)/port/host $(B)/$(v)/port/cortex-m $(B)/$(v)/gen $(B)/$(v)/bench)

# ------------------------------------------------------------------ single file (make amalgamate)
# dist/tinysubd.c (every src/*.c and src/*.h, one translation unit) and dist/tinysubd.h (the
# public headers), written by tools/amalgamate.sh. make test compiles dist/tinysubd.c alone (no
# include path: it needs only tinysubd.h beside it): with the host-float / host-fixed flags and
# sanitizers, linked with those variants' test objects (the same tests, the same hashes), and
# with the Cortex-M flags (-Werror, -Wstack-usage) for the link proofs; m4f-gnu as an
# integrator might build it, for the no-fused-multiply-add proof (test/scripts/amalgamate_test.sh).
AMALG := dist/tinysubd.c dist/tinysubd.h
$(AMALG) &: tools/amalgamate.sh $(SRC) $(wildcard src/*.h include/*.h)
	tools/amalgamate.sh dist
amalgamate: $(AMALG)

define amalg_host
$(B)/amalg-$(1)/tinysubd.o: dist/tinysubd.c $(AMALG) $(MK)
	@mkdir -p $$(@D)
	$(HOST_CC) $(WARN) $(SRC_WARN) $(HOST_FLAGS_host-$(1)) -c $$< -o $$@
$(B)/amalg-$(1)/test.elf: $(B)/amalg-$(1)/tinysubd.o $(filter-out $(SRC:%.c=$(B)/host-$(1)/%.o),$(call host_test_objs,host-$(1)))
	$(HOST_CC) $(SAN) $$^ -lm -o $$@
endef
$(foreach v,float fixed,$(eval $(call amalg_host,$(v))))
define amalg_cm
$(B)/amalg-$(1)/tinysubd.o: dist/tinysubd.c $(AMALG) $(MK)
	@mkdir -p $$(@D)
	$(CM_CC) $(ARCH_$(1)) $(CM_FLAGS) $(SRC_WARN) -DSUBD_FIXED=$(FIXED_$(1)) -c $$< -o $$@
$(B)/amalg-$(1)/libtinysubd.a: $(B)/amalg-$(1)/tinysubd.o
	rm -f $$@ && $(CM_AR) rcs $$@ $$^
endef
$(foreach v,m4f-float m3-fixed,$(eval $(call amalg_cm,$(v))))
$(B)/amalg-m4f-gnu/tinysubd.o: dist/tinysubd.c $(AMALG) $(MK)
	@mkdir -p $(@D)
	$(CM_CC) $(ARCH_m4f-float) $(GNU_WARN) $(SRC_WARN) -O2 -DSUBD_FIXED=0 -c $< -o $@
AMALG_BUILD := $(B)/amalg-float/test.elf $(B)/amalg-fixed/test.elf $(B)/amalg-m4f-float/libtinysubd.a \
               $(B)/amalg-m3-fixed/libtinysubd.a $(B)/amalg-m4f-gnu/tinysubd.o

# ------------------------------------------------------------------ toolchain
# A fresh Debian machine may have only gcc and make: install what is missing.
CM_OK = command -v $(CM_CC) >/dev/null 2>&1 && command -v qemu-system-arm >/dev/null 2>&1 && \
        command -v g++ >/dev/null 2>&1 && command -v cmake >/dev/null 2>&1 && \
        test -f /usr/lib/arm-none-eabi/lib/libc_nano.a
deps:
	@if ! ( $(CM_OK) ); then \
	    echo "installing gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm g++ cmake"; \
	    SUDO=; [ "$$(id -u)" -eq 0 ] || SUDO=sudo; \
	    $$SUDO apt-get update -q && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -q \
	        --no-install-recommends gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm g++ cmake \
	        || { echo "could not install the ARM toolchain / QEMU" >&2; exit 1; }; \
	fi

# ------------------------------------------------------------------ make test
L := $(B)/logs
# Seconds one device test image may run under QEMU (about 150 s on an idle core; raise it on a
# loaded machine: make test QEMU_TIMEOUT=1800).
QEMU_TIMEOUT ?= 600
# The build runs one job per core (make test is run without -j by CI and by users).
NPROC := $(shell nproc 2>/dev/null || echo 2)
# Building and running are one graph (the stages below, one target each, as soon as their
# inputs are built), so both cores stay busy: the QEMU runs, the longest, come first.
test: deps
	@$(MAKE) --no-print-directory -j$(NPROC) test-stages
	@test/scripts/summary.sh $(L)/*.log

# make test-host: the quick loop, host float and fixed tests only (ASan+UBSan), no QEMU.
test-host:
	@$(MAKE) --no-print-directory $(B)/host-float/test.elf $(B)/host-fixed/test.elf
	@rm -rf $(L) && mkdir -p $(L)
	@test/scripts/run_suite.sh "host-float tests" $(L)/host-float.log $(B)/host-float/test.elf
	@test/scripts/run_suite.sh "host-fixed tests" $(L)/host-fixed.log $(B)/host-fixed/test.elf
	@test/scripts/summary.sh $(L)/*.log

# make test-long: the host float/fixed tests (ASan+UBSan) with their long variants: the
# environment's SUBD_TEST_LONG=1 sets h_long (test/harness.h), which adds the deepest levels
# that make test leaves out (the 4-8 stream, shape and chordal sweeps). Not part of make test.
test-long:
	@$(MAKE) --no-print-directory $(B)/host-float/test.elf $(B)/host-fixed/test.elf
	@rm -rf $(L) && mkdir -p $(L)
	@SUBD_TEST_LONG=1 test/scripts/run_suite.sh "host-float tests (long)" $(L)/host-float.log $(B)/host-float/test.elf & \
	 SUBD_TEST_LONG=1 test/scripts/run_suite.sh "host-fixed tests (long)" $(L)/host-fixed.log $(B)/host-fixed/test.elf & wait
	@test/scripts/summary.sh $(L)/*.log

test-build: $(B)/host-float/test.elf $(B)/host-fixed/test.elf $(B)/host-float/test-fail.elf \
            m4f-float-images m3-fixed-images $(B)/m4f-float/libsubd.a $(B)/m3-fixed/libsubd.a tool \
            $(B)/host-gnu/test.elf $(B)/m4f-gnu/libsubd.a $(AMALG_BUILD)

# make test-run: the stages of make test on what is built (make test-build).
test-run:
	@$(MAKE) --no-print-directory -j$(NPROC) test-stages
	@test/scripts/summary.sh $(L)/*.log

# The stages of make test. Each prints one line (run_suite.sh) and writes $(L)/NAME.log;
# test-logs (order-only) clears the logs once, before the first.
R := test/scripts/run_suite.sh
test-logs:
	@rm -rf $(L) && mkdir -p $(L)
STAGES := m4f-float m3-fixed host-float host-fixed host-gnu amalg-float amalg-fixed self-m4f self-m3 tool \
          cmake fuzz-float fuzz-fixed cpp contract link-m4f link-m3 link-amalg-m4f link-amalg-m3 amalg \
          headers spdx hash-float hash-fixed hash-gnu hash-amalg-float hash-amalg-fixed
test-stages: $(STAGES:%=stage-%) test-build
stage-m4f-float: $(B)/m4f-float/test.elf | test-logs
	@$(R) "m4f-float tests (QEMU mps2-an386)" $(L)/m4f-float.log qemu/run.sh mps2-an386 $(B)/m4f-float/test.elf $(QEMU_TIMEOUT)
stage-m3-fixed: $(B)/m3-fixed/test.elf | test-logs
	@$(R) "m3-fixed tests (QEMU mps2-an385)" $(L)/m3-fixed.log qemu/run.sh mps2-an385 $(B)/m3-fixed/test.elf $(QEMU_TIMEOUT)
stage-host-float: $(B)/host-float/test.elf | test-logs
	@$(R) "host-float tests" $(L)/host-float.log $(B)/host-float/test.elf
stage-host-fixed: $(B)/host-fixed/test.elf | test-logs
	@$(R) "host-fixed tests" $(L)/host-fixed.log $(B)/host-fixed/test.elf
stage-hash-float: stage-host-float stage-m4f-float
	@$(R) "hashes host-float = m4f-float" $(L)/hash-float.log test/scripts/compare_hashes.sh $(L)/host-float.log $(L)/m4f-float.log float32
stage-hash-fixed: stage-host-fixed stage-m3-fixed
	@$(R) "hashes host-fixed = m3-fixed" $(L)/hash-fixed.log test/scripts/compare_hashes.sh $(L)/host-fixed.log $(L)/m3-fixed.log q16.16
stage-host-gnu: $(B)/host-gnu/test.elf | test-logs
	@if $(GNU_RUNS); then \
	    $(R) "host-gnu tests (gnu11 -O2 $(GNU_MARCH))" $(L)/host-gnu.log $(B)/host-gnu/test.elf; \
	else echo "== host-gnu tests: skipped (this CPU cannot run $(GNU_MARCH) code: no AVX2/FMA)"; fi
stage-hash-gnu: stage-host-float stage-host-gnu
	@if [ -f $(L)/host-gnu.log ]; then \
	    $(R) "hashes host-float = host-gnu" $(L)/hash-gnu.log test/scripts/compare_hashes.sh \
	        $(L)/host-float.log $(L)/host-gnu.log float32; fi
stage-contract: $(B)/m4f-gnu/libsubd.a $(B)/host-gnu/test.elf | test-logs
	@$(R) "contraction proofs (gnu11 builds)" $(L)/contract.log test/scripts/contract_proofs.sh \
	    $(CM_OBJDUMP) $(B)/m4f-gnu/libsubd.a $(B)/host-gnu/src
stage-link-m4f: $(B)/m4f-float/libsubd.a | test-logs
	@$(R) "link proofs m4f-float" $(L)/link-m4f.log test/scripts/link_proofs.sh $(CM_NM) $(B)/m4f-float/libsubd.a m4f-float
stage-link-m3: $(B)/m3-fixed/libsubd.a | test-logs
	@$(R) "link proofs m3-fixed" $(L)/link-m3.log test/scripts/link_proofs.sh $(CM_NM) $(B)/m3-fixed/libsubd.a m3-fixed
stage-self-m4f: m4f-float-images | test-logs
	@$(R) "harness self-test m4f-float" $(L)/self-m4f.log test/scripts/harness_selftest.sh mps2-an386 $(B)/m4f-float
stage-self-m3: m3-fixed-images | test-logs
	@$(R) "harness self-test m3-fixed" $(L)/self-m3.log test/scripts/harness_selftest.sh mps2-an385 $(B)/m3-fixed
stage-tool: tool | test-logs
	@$(R) "subd tool" $(L)/tool.log test/scripts/tool_test.sh $(B)/bin
stage-cpp: tool | test-logs
	@$(R) "C++ headers (g++ -std=c++11)" $(L)/cpp.log test/scripts/cpp_test.sh $(B)
stage-fuzz-float: $(B)/host-float/fuzz-replay | test-logs
	@$(R) "fuzz corpus replay host-float" $(L)/fuzz-float.log $(B)/host-float/fuzz-replay $(FUZZ_REPLAY_ARGS)
stage-fuzz-fixed: $(B)/host-fixed/fuzz-replay | test-logs
	@$(R) "fuzz corpus replay host-fixed" $(L)/fuzz-fixed.log $(B)/host-fixed/fuzz-replay $(FUZZ_REPLAY_ARGS)
stage-cmake: | test-logs
	@$(R) "cmake (add_subdirectory, install + find_package, Cortex-M cross)" $(L)/cmake.log test/scripts/cmake_test.sh $(B)
stage-amalg-float: $(B)/amalg-float/test.elf | test-logs
	@$(R) "amalgamation host-float tests" $(L)/amalg-float.log $(B)/amalg-float/test.elf
stage-amalg-fixed: $(B)/amalg-fixed/test.elf | test-logs
	@$(R) "amalgamation host-fixed tests" $(L)/amalg-fixed.log $(B)/amalg-fixed/test.elf
stage-hash-amalg-float: stage-host-float stage-amalg-float
	@$(R) "hashes host-float = amalgamation" $(L)/hash-amalg-float.log test/scripts/compare_hashes.sh \
	    $(L)/host-float.log $(L)/amalg-float.log float32
stage-hash-amalg-fixed: stage-host-fixed stage-amalg-fixed
	@$(R) "hashes host-fixed = amalgamation" $(L)/hash-amalg-fixed.log test/scripts/compare_hashes.sh \
	    $(L)/host-fixed.log $(L)/amalg-fixed.log q16.16
stage-link-amalg-m4f: $(B)/amalg-m4f-float/libtinysubd.a | test-logs
	@$(R) "link proofs amalgamation m4f-float" $(L)/link-amalg-m4f.log test/scripts/link_proofs.sh $(CM_NM) \
	    $(B)/amalg-m4f-float/libtinysubd.a m4f-float
stage-link-amalg-m3: $(B)/amalg-m3-fixed/libtinysubd.a | test-logs
	@$(R) "link proofs amalgamation m3-fixed" $(L)/link-amalg-m3.log test/scripts/link_proofs.sh $(CM_NM) \
	    $(B)/amalg-m3-fixed/libtinysubd.a m3-fixed
stage-amalg: $(B)/amalg-m4f-gnu/tinysubd.o | test-logs
	@$(R) "amalgamation (tools/amalgamate.sh)" $(L)/amalg.log test/scripts/amalgamate_test.sh \
	    $(CM_OBJDUMP) $(B)/amalg-m4f-gnu/tinysubd.o
stage-headers: | test-logs
	@$(R) "header template (include/*.h)" $(L)/headers.log test/scripts/header_check.sh include
stage-spdx: | test-logs
	@$(R) "SPDX license lines" $(L)/spdx.log test/scripts/spdx_check.sh .
.PHONY: test-logs test-stages $(STAGES:%=stage-%)

# ------------------------------------------------------------------ fuzzing (make fuzz)
# make fuzz [FUZZ_SECONDS=N]: libFuzzer targets (clang, ASan+UBSan, no recovery) for the OBJ
# reader, the OFF reader (+ tags), the STL and PLY readers and every scheme on decoded small meshes (fuzz/*.c), in
# float32 and Q16.16, each run N seconds by fuzz/run.sh. Installs clang when missing. Not part
# of make test; make test replays the committed corpus fuzz/corpus/<target>/ through the same
# checks built with gcc and the host sanitizers ("fuzz corpus replay" suites).
FUZZ_SECONDS ?= 60
CLANG ?= clang
FUZZ_TARGETS := obj off schemes stl ply ladapt sr48s
FUZZ_COMMON  := fuzz/fuzz_check.c fuzz/fuzz_reader.c fuzz/fuzz_mesh.c
FUZZ_SAN     := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_CFLAGS   = $(filter-out -Werror,$(WARN)) $(INC) -Ifuzz $(DEP) -DSUBD_HOST=1 -O1 -g $(FUZZ_SAN)
FIXED_fuzz-float := 0
FIXED_fuzz-fixed := 1

define fuzz_variant
$(B)/$(1)/src/%.o: src/%.c $(MK)
	@mkdir -p $$(@D)
	$(CLANG) $$(FUZZ_CFLAGS) -DSUBD_FIXED=$(FIXED_$(1)) -fsanitize=fuzzer-no-link -c $$< -o $$@
$(B)/$(1)/fuzz/%.o: fuzz/%.c $(MK)
	@mkdir -p $$(@D)
	$(CLANG) $$(FUZZ_CFLAGS) -DSUBD_FIXED=$(FIXED_$(1)) -fsanitize=fuzzer-no-link -c $$< -o $$@
$(B)/$(1)/fuzz_%: $(B)/$(1)/fuzz/fuzz_%.o $(FUZZ_COMMON:%.c=$(B)/$(1)/%.o) $(SRC:%.c=$(B)/$(1)/%.o)
	$(CLANG) -fsanitize=fuzzer $(FUZZ_SAN) $$^ -lm -o $$@
endef
$(foreach v,fuzz-float fuzz-fixed,$(eval $(call fuzz_variant,$(v))))
FUZZ_BINS := $(foreach v,fuzz-float fuzz-fixed,$(FUZZ_TARGETS:%=$(B)/$(v)/fuzz_%))
.SECONDARY: $(foreach v,fuzz-float fuzz-fixed,$(FUZZ_TARGETS:%=$(B)/$(v)/fuzz/fuzz_%.o) \
            $(FUZZ_COMMON:%.c=$(B)/$(v)/%.o) $(SRC:%.c=$(B)/$(v)/%.o))

fuzz:
	@if ! command -v $(CLANG) >/dev/null 2>&1; then \
	    echo "installing clang"; SUDO=; [ "$$(id -u)" -eq 0 ] || SUDO=sudo; \
	    $$SUDO apt-get update -q && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -q clang \
	        || { echo "could not install clang" >&2; exit 1; }; \
	fi
	@$(MAKE) --no-print-directory fuzz-build
	@fuzz/run.sh $(FUZZ_SECONDS) $(B)/fuzz-float $(B)/fuzz-fixed
fuzz-build: $(FUZZ_BINS)

# The corpus replay (fuzz/replay.c) with gcc and the host-float / host-fixed flags; each
# target's entry is renamed so that one program holds all three.
define fuzz_replay
$(B)/$(1)/fuzz/%.o: fuzz/%.c $(MK) | dirs
	@mkdir -p $$(@D)
	$(HOST_CC) $(WARN) $(INC) -Ifuzz $(DEP) $(HOST_FLAGS_$(1)) -c $$< -o $$@
$(B)/$(1)/fuzz/entry_%.o: fuzz/fuzz_%.c $(MK) | dirs
	@mkdir -p $$(@D)
	$(HOST_CC) $(WARN) $(INC) -Ifuzz $(DEP) $(HOST_FLAGS_$(1)) -DFUZZ_ENTRY=fz_$$*_entry -c $$< -o $$@
$(B)/$(1)/fuzz-replay: $(B)/$(1)/fuzz/replay.o $(FUZZ_TARGETS:%=$(B)/$(1)/fuzz/entry_%.o) \
        $(FUZZ_COMMON:%.c=$(B)/$(1)/%.o) $(SRC:%.c=$(B)/$(1)/%.o)
	$(HOST_CC) $(SAN) $$^ -lm -o $$@
endef
$(foreach v,host-float host-fixed,$(eval $(call fuzz_replay,$(v))))
FUZZ_REPLAY_ARGS := $(foreach t,$(FUZZ_TARGETS),$(t) fuzz/corpus/$(t))
test-build: $(B)/host-float/fuzz-replay $(B)/host-fixed/fuzz-replay
.PHONY: fuzz fuzz-build

# ------------------------------------------------------------------ CMake integration
# CMakeLists.txt, cmake/ and examples/ as a consumer uses them (test/scripts/cmake_test.sh): the example
# via add_subdirectory and via cmake --install + find_package, both arithmetics, and the library
# cross-built for Cortex-M4F with cmake/arm-none-eabi.cmake. Build trees in $(B)/cmake.
cmake-test: deps
	@test/scripts/cmake_test.sh $(B)
.PHONY: cmake-test

# ------------------------------------------------------------------ make demo / bench
demo: deps
	@$(MAKE) --no-print-directory demo-run

demo-run: $(B)/m4f-float/demo.elf $(B)/m3-fixed/demo.elf tool
	@mkdir -p $(B)/demo
	@echo "== firmware demo, Cortex-M4F float32 (QEMU mps2-an386)"
	@{ qemu/run.sh mps2-an386 $(B)/m4f-float/demo.elf 600; echo $$? > $(B)/demo/m4f-float.rc; } | tee $(B)/demo/m4f-float.log; exit $$(cat $(B)/demo/m4f-float.rc)
	@echo "== firmware demo, Cortex-M3 Q16.16 (QEMU mps2-an385)"
	@{ qemu/run.sh mps2-an385 $(B)/m3-fixed/demo.elf 600; echo $$? > $(B)/demo/m3-fixed.rc; } | tee $(B)/demo/m3-fixed.log; exit $$(cat $(B)/demo/m3-fixed.rc)
	@echo "== host tool (pictures in $(B)/demo/)"
	@demo/host_demo.sh $(B)/bin $(B)/demo
	@$(MAKE) --no-print-directory demo-pipe-check

# The pipeline demo (port/cortex-m/demo_pipe.c): its input as a C string, the brute-force
# measure the host half runs (demo/host_demo.sh), and the device checksum against the host's.
$(B)/gen/demo_pipe_obj.h: demo/spot_control_tri.obj $(MK) | dirs
	{ echo '/* generated from $< by the Makefile: its bytes and a 0 */'; echo 'static const char demo_pipe_obj[] = {'; \
	  od -An -v -tu1 $< | sed -e 's/\([0-9][0-9]*\)/\1,/g'; echo '0};'; } > $@
$(foreach v,m4f-float m3-fixed,$(B)/$(v)/port/cortex-m/demo_pipe.o): $(B)/gen/demo_pipe_obj.h
$(B)/bin/adapt_measure: test/tools/adapt_measure.c $(SRC) $(MK) | dirs
	$(HOST_CC) -std=c99 -O2 $(INC) -DSUBD_FIXED=0 test/tools/adapt_measure.c $(SRC) -lm -o $@
demo-run: $(B)/bin/adapt_measure
# Measures what an a-priori second-difference bound could do for 4-8 chordal cuts (not in make test).
$(B)/bin/sr48_bound: test/tools/sr48_bound.c $(SRC) port/host/fileio.c $(MK) | dirs
	$(HOST_CC) -std=c99 -O2 $(INC) -Iport/host -DSUBD_FIXED=0 test/tools/sr48_bound.c port/host/fileio.c $(SRC) -lm -o $@
demo-pipe-check:
	@dev=$$(sed -n 's/^  pipeline checksum //p' $(B)/demo/m4f-float.log); \
	host=$$(sed -n 's/.*"checksum":"\([0-9a-f]*\)".*/0x\1/p' $(B)/demo/pipe_stream_stats.json); \
	echo "== pipeline checksum: Cortex-M4F $$dev, host tool $$host"; test -n "$$dev" && test "$$dev" = "$$host"

bench: deps
	@$(MAKE) --no-print-directory bench-run

bench-run: $(B)/bench/bench $(B)/m4f-float/libsubd.a $(B)/m3-fixed/libsubd.a
	@echo "== host benchmark (make bench; $(HOST_CC) -O2)"
	@$(B)/bench/bench $(wildcard $(SHARED)/data/meshes/bench/*.obj)
	@$(B)/bench/bench -s valence48 $(wildcard $(SHARED)/data/meshes/*/*.obj)
	@echo "== Cortex-M library size (arm-none-eabi-size, -O2)"
	@$(CM_SIZE) -t $(B)/m4f-float/libsubd.a | tail -n 1 | sed 's/(TOTALS)/m4f-float libsubd.a/'
	@$(CM_SIZE) -t $(B)/m3-fixed/libsubd.a | tail -n 1 | sed 's/(TOTALS)/m3-fixed libsubd.a/'

# Same output as a reference commit (default HEAD: the uncommitted changes), byte for byte,
# on streamed and materialised cuts of the project's and the bench meshes, both arithmetics:
# make compare-ref REF=<commit>. Not part of make test (it builds the reference's tool).
REF ?= HEAD
compare-ref:
	@tools/compare_ref.sh $(REF) $(SHARED)

# Loop and Doo-Sabin next to OpenSubdiv, CGAL and OpenMesh (installs libosd-dev libcgal-dev
# libopenmesh-dev when missing); see bench/peers/README.md.
bench-peers:
	@bench/peers/run.sh $(SHARED)/data/meshes/bench

# Every float32 and Q16.16 bit pattern through subd_real_format against the bignum reference
# (test/ref_format.h) and back through subd_real_parse; host -O2, not part of make test (about
# an hour of CPU). FMT_RANGE="FIRST COUNT" checks a slice, e.g. FMT_RANGE="0x3f800000 1000000".
$(B)/bin/format_exhaustive-%: test/tools/format_exhaustive.c src/real_format.c src/real_text.c $(MK) | dirs
	$(HOST_CC) $(WARN) $(INC) -O2 -DSUBD_HOST=1 -DSUBD_FIXED=$(if $(filter fixed,$*),1,0) \
	    test/tools/format_exhaustive.c src/real_format.c src/real_text.c -o $@
check-format-exhaustive: $(B)/bin/format_exhaustive-float $(B)/bin/format_exhaustive-fixed
	$(B)/bin/format_exhaustive-float float $(FMT_RANGE)
	$(B)/bin/format_exhaustive-fixed q16 $(FMT_RANGE)

clean:
	rm -rf $(B) dist

# Header dependencies written by -MMD (none before the first build).
-include $(wildcard $(foreach v,$(VARIANTS) fuzz-float fuzz-fixed,$(B)/$(v)/*.d $(B)/$(v)/*/*.d $(B)/$(v)/*/*/*.d))

.PHONY: dirs deps test test-host test-long test-build test-run demo demo-run bench bench-run bench-peers compare-ref tool clean amalgamate \
        check-format-exhaustive \
        m4f-float-images m3-fixed-images
