// ELF checks before dlopen (see module_check.h).
#include "pipeline/module_check.h"

#include <elf.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

namespace svgm {

namespace fs = std::filesystem;

namespace {

// The ELF flavour this process is: a module of another class or byte order cannot load.
#if UINTPTR_MAX == 0xffffffffffffffffu
using Ehdr = Elf64_Ehdr;
using Phdr = Elf64_Phdr;
constexpr unsigned char kClass = ELFCLASS64;
#else
using Ehdr = Elf32_Ehdr;
using Phdr = Elf32_Phdr;
constexpr unsigned char kClass = ELFCLASS32;
#endif
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
constexpr unsigned char kData = ELFDATA2LSB;
#else
constexpr unsigned char kData = ELFDATA2MSB;
#endif

std::string truncated(uint64_t size, const char* what, uint64_t end) {
  return "truncated: " + std::to_string(size) + " bytes, but its " + what + " end at " +
         std::to_string(end);
}

// a + b * c, or UINT64_MAX when that overflows (a corrupt header, never a real offset).
uint64_t end_of(uint64_t a, uint64_t b, uint64_t c) {
  if (c != 0 && b > (UINT64_MAX - a) / c) return UINT64_MAX;
  return a + b * c;
}

}  // namespace

std::optional<std::string> module_problem(const fs::path& file) {
  std::error_code ec;
  // Not regular: a FIFO would block dlopen (and this check) forever.
  if (!fs::is_regular_file(file, ec)) return "not a regular file";
  const uint64_t size = fs::file_size(file, ec);
  if (ec) return "cannot read: " + ec.message();
  std::ifstream f(file, std::ios::binary);
  if (!f) return "cannot read: " + std::string(std::strerror(errno));
  Ehdr eh{};
  if (size < sizeof eh || !f.read(reinterpret_cast<char*>(&eh), sizeof eh))
    return "shorter than an ELF header: " + std::to_string(size) + " bytes";
  if (std::memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0) return "not an ELF file";
  if (eh.e_ident[EI_CLASS] != kClass || eh.e_ident[EI_DATA] != kData)
    return "an ELF file of another word size or byte order";
  if (eh.e_type != ET_DYN) return "not a shared object";
  if (eh.e_phnum == 0 || eh.e_phentsize != sizeof(Phdr)) return "no usable program headers";
  const uint64_t ph_end = end_of(eh.e_phoff, eh.e_phnum, eh.e_phentsize);
  if (ph_end > size) return truncated(size, "program headers", ph_end);
  std::vector<Phdr> ph(eh.e_phnum);
  f.seekg(static_cast<std::streamoff>(eh.e_phoff));
  if (!f.read(reinterpret_cast<char*>(ph.data()), static_cast<std::streamsize>(ph.size() * sizeof(Phdr))))
    return truncated(size, "program headers", ph_end);
  // Loaded segments are mmapped page by page: file bytes past the end fault (SIGBUS).
  uint64_t seg_end = 0;
  for (const Phdr& p : ph)
    if (p.p_type == PT_LOAD || p.p_type == PT_DYNAMIC)
      seg_end = std::max<uint64_t>(seg_end, end_of(p.p_offset, p.p_filesz, 1));
  if (seg_end > size) return truncated(size, "segments", seg_end);
  // The loader does not map the section headers, but a file cut before them is no whole
  // module either (symbols and debug information are missing).
  if (eh.e_shoff != 0) {
    const uint64_t sh_end = end_of(eh.e_shoff, eh.e_shnum, eh.e_shentsize);
    if (sh_end > size) return truncated(size, "section headers", sh_end);
  }
  return std::nullopt;
}

}  // namespace svgm
