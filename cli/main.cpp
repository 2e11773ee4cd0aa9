#include "cli/application.h"

int main(int argc, char** argv) { return solidtex::cli::runApplication(argc, argv); }
