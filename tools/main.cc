// The `massprops` command-line tool (placeholder until the check command lands).
#include <iostream>
int main() { std::cout << "massprops " << MASSPROPS_VERSION << "\n"; }
