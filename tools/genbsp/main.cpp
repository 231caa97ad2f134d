// genbsp: the command-line program (its subcommands: commands.cpp).
#include "commands.hpp"

int main(int argc, char** argv) { return genbsp_tool::run_main(argc, argv); }
