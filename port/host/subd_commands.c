/* SPDX-License-Identifier: MIT */
/* subd tool: the command table. The plain commands (info, convert, render: no scheme) are
 * described here; every scheme command is a descriptor its module exports (cmd_*.c: its
 * options, checks, plan, run, stream and description). The table's order is --help's. This
 * is the one place that lists the schemes; the common path reaches them only through the
 * descriptors' function pointers.
 */
#include <string.h>
#include "subd_tool.h"

static const command cmd_info = {
    .name = "info",
    .canonical = "info",
    .synopsis = "INPUT",
    .summary = "counts, components, Euler characteristic, genus,\n"
               "valences and bounding box of a mesh",
    .flags = CMD_OUTPUT_NONE,
    .report = tool_info_report,
};

static const command cmd_convert = {
    .name = "convert",
    .canonical = "convert",
    .synopsis = "INPUT -o OUTPUT",
    .summary = "write the mesh in OUTPUT's format",
    .flags = CMD_OUTPUT_REQUIRED,
};

static const command cmd_render = {
    .name = "render",
    .canonical = "render",
    .synopsis = "INPUT -o OUTPUT.png",
    .summary = "draw the mesh (shaded, with edges) as a PNG",
    .flags = CMD_OUTPUT_REQUIRED | CMD_PNG_ONLY,
};

const command *const tool_commands[] = {
    &cmd_info, &cmd_convert, &cmd_render, &tool_cmd_loop, &tool_cmd_limit, &tool_cmd_pia, &tool_cmd_quasi48,
    &tool_cmd_alpha, &tool_cmd_sr48, &tool_cmd_semireg48, &tool_cmd_adapt, NULL,
};

const command *tool_find_command(const char *name)
{
    size_t i;
    for (i = 0; tool_commands[i]; i++)
        if (strcmp(tool_commands[i]->name, name) == 0) return tool_commands[i];
    return NULL;
}
