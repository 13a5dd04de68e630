#pragma once
#include <httplib.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace aerobreak {

// Range requests (RFC 9110 14), answered the way common servers bound them (Apache after
// CVE-2011-3192, Go's ServeContent): the parts are resolved against the answer's length, the
// unsatisfiable ones dropped, the rest sorted and overlapping or adjacent parts merged; none left
// is 416 with "Content-Range: bytes */LENGTH"; one is 206 with that part; 2 to kMaxRangeParts a
// multipart/byteranges 206; more than kMaxRangeParts, or several of a streamed answer longer than
// kMaxGatheredBytes (a large case file), are the whole answer (200, as RFC 9110 14.2 allows a
// server to ignore Range). So no Range header can make an answer longer than the whole answer plus
// kMaxRangeParts part headers.
constexpr std::size_t kMaxRangeParts = 8;
// The longest streamed answer read into memory to cut several parts from.
constexpr std::size_t kMaxGatheredBytes = std::size_t{1} << 20;

// One part, both ends included, as resolved against an answer of known length.
struct ByteRange {
  std::uint64_t first = 0;
  std::uint64_t last = 0;
};

// What a Range header asks of an answer of `length` bytes.
struct RangePlan {
  enum class Kind { whole, partial, unsatisfiable } kind = Kind::whole;
  std::vector<ByteRange> parts;  // partial: sorted, disjoint, not adjacent; at most kMaxRangeParts
};

// The plan for a Range header value ("bytes=0-99,-500"); a value that is not a byte-range set
// (another unit, bad syntax) is ignored: the whole answer.
RangePlan plan_byte_ranges(std::string_view header, std::uint64_t length);

// Applies the request's Range header to a 200 answer to GET about to be sent (the server's
// post-routing handler): the library's own range handling is switched off for every request
// (BoundedServer), so that this is the only one. An If-Range that does not name the answer's ETag
// asks for the whole answer.
void apply_byte_ranges(const httplib::Request& request, httplib::Response& response);

}  // namespace aerobreak
