// Writes data/rgb_spectrum_coefficients.csv to standard output: the Jakob–Hanika fit
// at every node of the RGB table (spectrum/rgb_spectrum_table.h). Run by
// scripts/make-rgb-spectrum-table.sh; about 2 s of CPU.
#include <iostream>

#include "skylit/spectrum/rgb_spectrum_table.h"

int main() {
  std::cout << skylit::rgb_table_csv(skylit::fit_rgb_table_nodes());
  return 0;
}
