// Reads the records of a generated data file: its path, its header's hash and its inputs fingerprint.
#include "data_file_records.hpp"

#include <filesystem>

#include "generated_format.hpp"
#include "prism/hash/content_hash.hpp"

namespace prism::shaderc {

std::string dataPathFor(const std::string& headerPath) {
    return std::filesystem::path(headerPath).replace_extension(format::kDataFileExtension).string();
}

std::string headerHash(const std::string& headerText) {
    return hash::ContentHash().add(headerText).hex64();
}

bool headerMatchesData(const std::string& headerText, const std::string& dataText) {
    const auto pos = dataText.rfind(format::kHeaderHashLine);
    if (pos == std::string::npos || headerText.empty()) return false;
    const auto recorded = pos + format::kHeaderHashLine.size();
    return dataText.compare(recorded, format::kHashDigits + 1, headerHash(headerText) + "\n") == 0;
}

std::string recordedFingerprint(const std::string& text) {
    const auto pos = text.find(format::kFingerprintLine);
    if (pos == std::string::npos || pos > format::kFingerprintWithin) return {};  // the banner's second line only
    const auto start = pos + format::kFingerprintLine.size();
    const auto end = text.find('\n', pos);
    return text.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

}  // namespace prism::shaderc
