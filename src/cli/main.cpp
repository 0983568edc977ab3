// swarf: the command-line front end (a thin layer over libswarf).
#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--version") == 0) {
    std::printf("swarf %s\n", SWARF_VERSION);
    return 0;
  }
  std::fprintf(stderr, "usage: swarf --version\n");
  return 2;
}
