#pragma once
/// \file uncertainty_file.hpp
/// Reads a ProcessUncertainty from a JSON or TOML file (by extension: .json, .toml): one key
/// per uncertain input, its value the distribution's text form (docs/robust-design.md), e.g.
///   mu = "normal:0.2,5%"          (TOML)      {"mu": "normal:0.2,5%"}   (JSON)
///   c_mu = "normal:2.5,0.125,2,3"
///   width = "samples:0.00298,0.00301,0.00303"
///   x_mu_offset = "interval:-2e-4,2e-4"
/// The file is read by read_document (io/document.hpp: registered as the --uncertainty-file
/// input, at most 2 levels deep). Throws InvalidParameter naming the file (and the line and
/// column) or the key on unreadable or malformed files, unknown keys and invalid
/// distributions.

#include <string>

#include "selfalign/robust/process_uncertainty.hpp"

namespace selfalign {

ProcessUncertainty load_uncertainty(const std::string& path);

}  // namespace selfalign
