# tinysubd — every entry point. See README.md.
#   make test    everything a change must pass (host float/fixed with ASan+UBSan, QEMU
#                Cortex-M4F float and Cortex-M3 fixed, host = QEMU hashes, link-time proofs)
#   make demo    firmware demo in QEMU + host tool on bundled meshes -> build/demo/
#   make bench   performance report (never part of make test)

.SUFFIXES:
.DELETE_ON_ERROR:
B := build

SRC      := $(sort $(wildcard src/*.c))
TEST_SRC := $(sort $(wildcard test/test_*.c)) test/harness.c

WARN := -std=c99 -Wall -Wextra -Werror -pedantic -Wshadow -Wvla -Wdouble-promotion \
        -Wstrict-prototypes -Wmissing-prototypes -ffp-contract=off
SRC_WARN := -Wconversion -Wsign-conversion
INC := -Iinclude -Itest -I$(B)/gen

# ---------------------------------------------------------------- host variants
HOST_CC  ?= gcc
SAN      := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
HOST_OPT := -O1 -g
host_flags = $(WARN) $(INC) -DSUBD_HOST=1 -DSUBD_FIXED=$(1)

$(B)/host-float/src/%.o: src/%.c $(wildcard include/*.h) | dirs
	$(HOST_CC) $(call host_flags,0) $(SRC_WARN) $(HOST_OPT) $(SAN) -c $< -o $@
$(B)/host-fixed/src/%.o: src/%.c $(wildcard include/*.h) | dirs
	$(HOST_CC) $(call host_flags,1) $(SRC_WARN) $(HOST_OPT) $(SAN) -c $< -o $@
$(B)/host-float/test/%.o: test/%.c $(wildcard include/*.h test/*.h) $(B)/gen/corpus.h $(B)/gen/readme_example.c | dirs
	$(HOST_CC) $(call host_flags,0) $(HOST_OPT) $(SAN) -c $< -o $@
$(B)/host-fixed/test/%.o: test/%.c $(wildcard include/*.h test/*.h) $(B)/gen/corpus.h $(B)/gen/readme_example.c | dirs
	$(HOST_CC) $(call host_flags,1) $(HOST_OPT) $(SAN) -c $< -o $@
$(B)/host-float/port/%.o: port/%.c $(wildcard include/*.h test/*.h port/host/*.h) | dirs
	$(HOST_CC) $(call host_flags,0) $(HOST_OPT) $(SAN) -c $< -o $@
$(B)/host-fixed/port/%.o: port/%.c $(wildcard include/*.h test/*.h port/host/*.h) | dirs
	$(HOST_CC) $(call host_flags,1) $(HOST_OPT) $(SAN) -c $< -o $@

HOST_TEST_PORT := port/host/test_port.c port/host/png.c port/host/render.c
host_test_objs = $(SRC:%.c=$(B)/$(1)/%.o) $(TEST_SRC:%.c=$(B)/$(1)/%.o) $(B)/$(1)/gen/corpus.o $(HOST_TEST_PORT:%.c=$(B)/$(1)/%.o)

$(B)/host-float/test.elf: $(call host_test_objs,host-float)
	$(HOST_CC) $(SAN) $^ -lm -o $@
$(B)/host-fixed/test.elf: $(call host_test_objs,host-fixed)
	$(HOST_CC) $(SAN) $^ -lm -o $@

# ---------------------------------------------------------------- generated test corpus
# Test inputs (test/data, test/bad) are embedded as C arrays so the same files reach QEMU.
$(B)/gen/embed: test/tools/embed.c | dirs
	$(HOST_CC) -std=c99 -O1 -Wall -Werror $< -o $@
CORPUS := $(sort $(wildcard test/data/*) $(wildcard test/bad/*))
$(B)/gen/corpus.c $(B)/gen/corpus.h &: $(B)/gen/embed $(CORPUS)
	$(B)/gen/embed $(B)/gen/corpus.c $(B)/gen/corpus.h $(CORPUS)
$(B)/host-float/gen/corpus.o: $(B)/gen/corpus.c | dirs
	$(HOST_CC) $(call host_flags,0) $(HOST_OPT) $(SAN) -c $< -o $@
$(B)/host-fixed/gen/corpus.o: $(B)/gen/corpus.c | dirs
	$(HOST_CC) $(call host_flags,1) $(HOST_OPT) $(SAN) -c $< -o $@

# The README's embedding example is compiled by the tests (test/test_embed.c).
$(B)/gen/readme_example.c: README.md | dirs
	awk '/^<!-- embed-example/{f=1;next} f&&/^```c/{g=1;next} g&&/^```/{exit} g{print}' $< > $@
	@test -s $@ || { echo "README.md: embed-example block not found" >&2; exit 1; }

dirs:
	@mkdir -p $(B)/gen $(foreach v,host-float host-fixed m4f-float m3-fixed,$(B)/$(v)/src $(B)/$(v)/test $(B)/$(v)/port/host $(B)/$(v)/port/cortex-m $(B)/$(v)/gen)

host-test: $(B)/host-float/test.elf $(B)/host-fixed/test.elf
	$(B)/host-float/test.elf
	$(B)/host-fixed/test.elf

.PHONY: dirs host-test test demo bench clean
clean:
	rm -rf $(B)
