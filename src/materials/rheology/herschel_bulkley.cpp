#include "materials/rheology/herschel_bulkley.hpp"

namespace partimix::materials {

HerschelBulkley::HerschelBulkley(const YieldRegularisation& yield, double consistency,
                                 double flow_index)
    : yield_(yield), power_law_(consistency, flow_index) {}

double HerschelBulkley::apparent_viscosity(double shear_rate) const {
  return yield_.viscosity(shear_rate) + power_law_.apparent_viscosity(shear_rate);
}

}  // namespace partimix::materials
