// The file seam on Windows: UTF-8 paths become UTF-16 for the wide API; a save is a new file,
// FlushFileBuffers, then ReplaceFileW over the target (which keeps its attributes and ACL), or
// MoveFileExW(WRITE_THROUGH) for a new one; both retried for a while on sharing violations.
#include "io/platform_file.hpp"

#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#ifndef NOMINMAX  // MinGW's libstdc++ defines it already
#define NOMINMAX
#endif
#include <windows.h>

#include "verve/error.hpp"

namespace verve::io::platform {
namespace {

std::string systemMessage(DWORD code) {
    char* text = nullptr;
    const DWORD n = ::FormatMessageA(FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM |
                                         FORMAT_MESSAGE_IGNORE_INSERTS,
                                     nullptr, code, 0, reinterpret_cast<char*>(&text), 0, nullptr);
    std::string message = n > 0 ? std::string(text, n) : "error " + std::to_string(code);
    if (text != nullptr) ::LocalFree(text);
    while (!message.empty() && (message.back() == '\n' || message.back() == '\r' || message.back() == '.')) {
        message.pop_back();
    }
    return message;
}

[[noreturn]] void fail(const std::string& what, const std::string& path, DWORD code) {
    throw Error(ErrorCode::Io, what + " '" + path + "': " + systemMessage(code));
}

std::wstring wide(const std::string& utf8) {
    if (utf8.empty()) return std::wstring();
    const int size = static_cast<int>(utf8.size());
    const int n = ::MultiByteToWideChar(CP_UTF8, MB_ERR_INVALID_CHARS, utf8.data(), size, nullptr, 0);
    if (n <= 0) throw Error(ErrorCode::InvalidArgument, "the path '" + utf8 + "' is not valid UTF-8");
    std::wstring out(static_cast<std::size_t>(n), L'\0');
    ::MultiByteToWideChar(CP_UTF8, MB_ERR_INVALID_CHARS, utf8.data(), size, &out[0], n);
    return out;
}

std::string narrow(const wchar_t* utf16) {
    const int n = ::WideCharToMultiByte(CP_UTF8, 0, utf16, -1, nullptr, 0, nullptr, nullptr);
    if (n <= 1) return std::string();
    std::string out(static_cast<std::size_t>(n), '\0');
    ::WideCharToMultiByte(CP_UTF8, 0, utf16, -1, &out[0], n, nullptr, nullptr);
    out.pop_back();  // the terminating NUL
    return out;
}

class Handle {
public:
    explicit Handle(HANDLE h) : h_(h) {}
    ~Handle() { close(); }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    HANDLE get() const { return h_; }
    bool valid() const { return h_ != INVALID_HANDLE_VALUE; }
    bool close() {
        const bool ok = !valid() || ::CloseHandle(h_) != 0;
        h_ = INVALID_HANDLE_VALUE;
        return ok;
    }

private:
    HANDLE h_;
};

constexpr DWORD kChunk = 1u << 30;  // ReadFile/WriteFile take a DWORD count

}  // namespace

const char* pathSeparators() { return "\\/"; }

std::string followLinks(const std::string& path) { return path; }

// `replacing`: ReplaceFileW gives the new file the replaced one's attributes and ACL (replaceFile).
bool writeNewFile(const std::string& path, const std::string& data, const std::string& /*replacing*/) {
    const std::wstring name = wide(path);
    Handle file(::CreateFileW(name.c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW, FILE_ATTRIBUTE_NORMAL, nullptr));
    if (!file.valid()) {
        const DWORD code = ::GetLastError();
        if (code == ERROR_FILE_EXISTS || code == ERROR_ALREADY_EXISTS) return false;
        fail("cannot create", path, code);
    }
    try {
        const char* p = data.data();
        std::size_t left = data.size();
        while (left > 0) {
            DWORD written = 0;
            const DWORD chunk = left < kChunk ? static_cast<DWORD>(left) : kChunk;
            if (!::WriteFile(file.get(), p, chunk, &written, nullptr)) fail("cannot write", path, ::GetLastError());
            p += written;
            left -= written;
        }
        if (!::FlushFileBuffers(file.get())) fail("cannot flush", path, ::GetLastError());
        if (!file.close()) fail("cannot close", path, ::GetLastError());
    } catch (...) {
        file.close();
        ::DeleteFileW(name.c_str());
        throw;
    }
    return true;
}

namespace {

// Another handle on the file (a load without FILE_SHARE_DELETE in another program, an antivirus
// or an indexer scanning the new save) makes a replace fail for a moment: worth waiting for.
bool transient(DWORD code) {
    return code == ERROR_SHARING_VIOLATION || code == ERROR_LOCK_VIOLATION || code == ERROR_ACCESS_DENIED ||
           code == ERROR_UNABLE_TO_REMOVE_REPLACED || code == ERROR_UNABLE_TO_MOVE_REPLACEMENT;
}

}  // namespace

void replaceFile(const std::string& from, const std::string& to) {
    const std::wstring source = wide(from), target = wide(to);
    DWORD code = ERROR_SUCCESS;
    // About 2 s in all: long enough for a scanner, short enough not to hang a game's save.
    for (int attempt = 0; attempt < 40; ++attempt) {
        if (attempt > 0) ::Sleep(attempt < 10 ? 10 : 60);
        if (::ReplaceFileW(target.c_str(), source.c_str(), nullptr, REPLACEFILE_IGNORE_MERGE_ERRORS, nullptr, nullptr)) {
            return;
        }
        code = ::GetLastError();
        if (code == ERROR_FILE_NOT_FOUND || code == ERROR_UNABLE_TO_MOVE_REPLACEMENT_2) {
            // No file to replace (a first save), or it was moved aside and the new one is still
            // under its temporary name: move the new one into place.
            if (::MoveFileExW(source.c_str(), target.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) return;
            code = ::GetLastError();
        }
        if (!transient(code)) break;
    }
    fail("cannot replace", to, code);
}

void removeFile(const std::string& path) noexcept {
    try {
        ::DeleteFileW(wide(path).c_str());
    } catch (...) {
    }
}

std::vector<std::string> listDirectory(const std::string& directory) {
    std::vector<std::string> names;
    WIN32_FIND_DATAW entry;
    const HANDLE find = ::FindFirstFileW(wide(joinPath(directory.empty() ? "." : directory, "*")).c_str(), &entry);
    if (find == INVALID_HANDLE_VALUE) return names;
    do {
        names.push_back(narrow(entry.cFileName));
    } while (::FindNextFileW(find, &entry));
    ::FindClose(find);
    return names;
}

std::uint64_t currentProcessId() { return ::GetCurrentProcessId(); }

std::string placeTag() {
    static const std::string tag = [] {
        wchar_t name[256] = {};
        DWORD size = 255;
        std::string place = ::GetComputerNameExW(ComputerNameDnsFullyQualified, name, &size) ? narrow(name) : "";
        std::uint32_t hash = 2166136261u;
        for (const unsigned char c : place) hash = (hash ^ c) * 16777619u;
        static const char digits[] = "0123456789abcdef";
        std::string hex(8, '0');
        for (int i = 7; i >= 0; --i, hash >>= 4) hex[static_cast<std::size_t>(i)] = digits[hash & 15];
        return hex;
    }();
    return tag;
}

bool processIsRunning(std::uint64_t pid) {
    if (pid == 0 || pid > 0xFFFFFFFFu) return true;  // not a process id: leave its file alone
    const HANDLE process = ::OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, static_cast<DWORD>(pid));
    if (process == nullptr) return ::GetLastError() != ERROR_INVALID_PARAMETER;  // only "no such process" is gone
    DWORD exitCode = 0;
    const BOOL known = ::GetExitCodeProcess(process, &exitCode);
    ::CloseHandle(process);
    return !known || exitCode == STILL_ACTIVE;
}

std::string readRegularFile(const std::string& path, std::uint64_t maxBytes) {
    // FILE_SHARE_DELETE: a save (ReplaceFileW, MoveFileExW) may replace the file while it is read.
    Handle file(::CreateFileW(wide(path).c_str(), GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE,
                              nullptr, OPEN_EXISTING, FILE_ATTRIBUTE_NORMAL, nullptr));
    if (!file.valid()) fail("cannot open", path, ::GetLastError());
    if (::GetFileType(file.get()) != FILE_TYPE_DISK) refuseNonRegular(path);
    LARGE_INTEGER size;
    if (!::GetFileSizeEx(file.get(), &size)) fail("cannot read", path, ::GetLastError());
    if (static_cast<std::uint64_t>(size.QuadPart) > maxBytes) refuseTooLarge(path, maxBytes);
    std::string data(static_cast<std::size_t>(size.QuadPart), '\0');
    std::size_t done = 0;
    while (done < data.size()) {
        DWORD got = 0;
        const std::size_t left = data.size() - done;
        const DWORD chunk = left < kChunk ? static_cast<DWORD>(left) : kChunk;
        if (!::ReadFile(file.get(), &data[done], chunk, &got, nullptr)) fail("cannot read", path, ::GetLastError());
        if (got == 0) break;  // it shrank
        done += got;
    }
    data.resize(done);
    return data;
}

}  // namespace verve::io::platform
