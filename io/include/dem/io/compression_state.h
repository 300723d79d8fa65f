// The plate loading analyses' state (analysis::CompressionStateT) as text,
// for checkpoints (checkpoint_store.h, ResumePoint::analysis): the samples
// and the contact snapshots taken so far, every double in the shortest form
// that reads back to the same bits.
#pragma once

#include <string>
#include <string_view>

#include "dem/analysis/compression_analysis.h"

namespace dem::io {

template <int Dim>
std::string compression_state_text(const analysis::CompressionStateT<Dim>& state);

// Throws std::runtime_error, saying what is wrong, for text that is not such a state.
template <int Dim>
analysis::CompressionStateT<Dim> compression_state_from_text(std::string_view text);

extern template std::string compression_state_text(const analysis::CompressionStateT<2>&);
extern template std::string compression_state_text(const analysis::CompressionStateT<3>&);
extern template analysis::CompressionStateT<2> compression_state_from_text<2>(std::string_view);
extern template analysis::CompressionStateT<3> compression_state_from_text<3>(std::string_view);

}  // namespace dem::io
