// hmcr: entry point; the command line lives in cli.cpp.
namespace hmcr {
int run_cli(int argc, char** argv);
}

int main(int argc, char** argv) { return hmcr::run_cli(argc, argv); }
