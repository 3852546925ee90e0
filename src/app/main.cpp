#include "app/cli.hpp"

int main(int argc, char** argv) { return glintlab::run_cli(argc, argv); }
