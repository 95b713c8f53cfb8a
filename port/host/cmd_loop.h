/* SPDX-License-Identifier: MIT */
/* subd tool: what the Loop commands (cmd_loop.c) share with pia (cmd_pia.c), which runs on
 * Loop's limit operator: the --boundary rule and its description. */
#ifndef CMD_LOOP_H
#define CMD_LOOP_H
#include "subd_tool.h"

/* --boundary paper|bspline (default paper) into o->boundary; EXIT_OK or a usage error. */
int tool_loop_boundary(const command *cmd, tool_opts *o);
/* " --boundary bspline" and " --crease-angle D" when given (command.describe). */
size_t tool_loop_describe_rules(const tool_opts *o, char *buf, size_t k, size_t n);
#endif
