#include <iostream>
#include "core/version.h"
int main() { std::cout << "vlit " << vlit::kVersion << "\n"; return 0; }
