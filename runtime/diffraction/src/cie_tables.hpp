// The raw CIE tables as read from colord-data at build time (generated cie_tables.cpp in the
// build tree). Private to prism_diffraction_core; colour.hpp is the public interface.
#pragma once

namespace prism::diffraction::detail {

struct CieSourceTables {
    double cmfStartNm, cmfStepNm;
    int cmfCount;
    const double *x, *y, *z;
    double d65StartNm, d65StepNm;
    int d65Count;
    const double* d65;
    const char* cmfSource;
    const char* d65Source;
};

const CieSourceTables& cieSourceTables();

}  // namespace prism::diffraction::detail
