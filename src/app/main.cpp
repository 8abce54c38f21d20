#include <cstdio>

int main() {
  std::puts("partimix");
  return 0;
}
