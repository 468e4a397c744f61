// Number and text formatting shared by the report's HTML and CSV, so a test can look for
// exactly the string the report prints.
#pragma once

#include <string>

#include "protocols/io/xml_escape.h"  // escapeXml, used with these by every report writer

namespace protocols {

// "83.3 %" (one decimal); the report prints every coverage fraction this way.
std::string formatPercent(double fraction);
// "%.*g"-style with `digits` significant digits, e.g. formatNumber(0.000812, 3) = "0.000812".
std::string formatNumber(double value, int digits = 4);

}  // namespace protocols
