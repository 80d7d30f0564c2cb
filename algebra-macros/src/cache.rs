//! The expansion cache: an `algebra!` invocation whose tokens and generator are unchanged since
//! the last build reads its expansion back instead of planning and emitting it again.
//!
//! Rebuilding a crate after an edit elsewhere in the file that declares the algebra re-runs the
//! macro; for a 3D PGA module the plan and the emission took about 0.13 s of a 0.6 s debug
//! rebuild (docs/performance.md, "Rebuilding a crate that declares an algebra"). The expansion
//! depends only on the invocation's tokens and on the generator's code, so both are the key:
//!
//! - the invocation, as text (`TokenStream::to_string`), compared in full, not by hash;
//! - the generator: the path, size, modification time and inode of the dynamic library this
//!   macro was loaded from (found in `/proc/self/maps` from the address of one of its
//!   functions), which any rebuild of the macro or of a crate it links replaces. The file on
//!   disk must still be the mapped one (same inode): a long-running process holding an older
//!   build neither reads nor writes entries.
//!
//! Entries live beside that library, in `gam-algebra-cache/` of the target's profile directory
//! (`target/debug/`), so `cargo clean` removes them and nothing is written outside the build.
//! One file per (crate, module name): an edit of the declaration overwrites its entry, so the
//! cache holds one expansion per declared module. Writes go through a temporary file and a
//! rename, so concurrent builds never read half an entry.
//!
//! Anything unexpected (no `/proc`, a read-only target, a cache directory owned by another user
//! or writable by others, `GAM_ALGEBRA_CACHE=off` in the environment) turns the cache off for
//! that expansion: the macro then computes it, as without
//! a cache. Linux only; elsewhere it always computes.

use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};

/// What identifies an expansion: the invocation's text and the generator's library.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Key {
    /// The entry's file.
    file: PathBuf,
    /// The first line of the entry: the generator's identity and the invocation, escaped to one
    /// line.
    header: String,
}

impl Key {
    /// The key of an invocation, or `None` when the cache is off or unavailable.
    pub(crate) fn new(invocation: &str, module: &str) -> Option<Key> {
        if std::env::var_os("GAM_ALGEBRA_CACHE").is_some_and(|v| v == "off") {
            return None;
        }
        let (library, inode) = own_library()?;
        let meta = std::fs::metadata(&library).ok()?;
        // the file on disk must be the one loaded: a long-running process (an editor's
        // proc-macro server) may hold an older build whose file was since replaced
        if !same_inode(&meta, inode) {
            return None;
        }
        let dir = library.parent()?.parent()?.join("gam-algebra-cache");
        if !trusted(&dir, &meta) {
            return None;
        }
        let crate_id = format!(
            "{}/{}",
            std::env::var("CARGO_MANIFEST_DIR").unwrap_or_default(),
            std::env::var("CARGO_CRATE_NAME").unwrap_or_default()
        );
        Some(Key::at(&dir, &crate_id, module, &identity(&library, &meta), invocation))
    }

    /// The key of an invocation with an explicit cache directory and generator identity.
    pub(crate) fn at(dir: &Path, crate_id: &str, module: &str, generator: &str, invocation: &str) -> Key {
        let mut h = std::collections::hash_map::DefaultHasher::new();
        (crate_id, module).hash(&mut h);
        let file = dir.join(format!("{module}-{:016x}.rs", h.finish()));
        let header = format!("// {generator} {}", invocation.replace('\\', "\\\\").replace('\n', "\\n"));
        Key { file, header }
    }

    /// The cached expansion, when the entry exists, its header is this key's and its body is
    /// the one stored (length and hash: a damaged entry is a miss, since the caller hands the
    /// text to the compiler's lexer unchecked).
    pub(crate) fn lookup(&self) -> Option<String> {
        let text = std::fs::read_to_string(&self.file).ok()?;
        let (header, rest) = text.split_once('\n')?;
        let (check, body) = rest.split_once('\n')?;
        (header == self.header && check == checksum(body)).then(|| body.to_string())
    }

    /// Stores an expansion (errors ignored: the cache is an optimisation).
    pub(crate) fn store(&self, expansion: &str) {
        let Some(dir) = self.file.parent() else { return };
        if std::fs::create_dir_all(dir).is_err() {
            return;
        }
        let tmp = self.file.with_extension(format!("tmp{}", std::process::id()));
        let text = format!("{}\n{}\n{expansion}", self.header, checksum(expansion));
        if std::fs::write(&tmp, text).is_err() || std::fs::rename(&tmp, &self.file).is_err() {
            let _ = std::fs::remove_file(&tmp);
        }
    }
}

/// Whether entries may be read from `dir`: on Unix it must be absent (it will be created) or a
/// directory owned by the library's owner and writable by no one else, so another user cannot
/// plant an expansion (code the compiler would build) in it.
fn trusted(dir: &Path, library: &std::fs::Metadata) -> bool {
    match std::fs::symlink_metadata(dir) {
        Err(e) => e.kind() == std::io::ErrorKind::NotFound,
        #[cfg(unix)]
        Ok(m) => {
            use std::os::unix::fs::MetadataExt;
            m.is_dir() && m.uid() == library.uid() && m.mode() & 0o022 == 0
        }
        #[cfg(not(unix))]
        Ok(m) => m.is_dir() && library.is_file(),
    }
}

/// The second line of an entry: the body's length and hash.
fn checksum(body: &str) -> String {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    body.hash(&mut h);
    format!("// {} {:016x}", body.len(), h.finish())
}

/// The generator's identity: its library's path, size, modification time and inode.
fn identity(library: &Path, meta: &std::fs::Metadata) -> String {
    let modified = meta.modified().ok().and_then(|t| t.duration_since(std::time::UNIX_EPOCH).ok());
    #[cfg(unix)]
    let inode = std::os::unix::fs::MetadataExt::ino(meta);
    #[cfg(not(unix))]
    let inode = 0u64;
    format!("{} {} {:?} {inode}", library.display(), meta.len(), modified.map(|d| d.as_nanos()))
}

/// Whether `meta` is the file of the mapped inode.
fn same_inode(meta: &std::fs::Metadata, inode: u64) -> bool {
    #[cfg(unix)]
    return std::os::unix::fs::MetadataExt::ino(meta) == inode;
    #[cfg(not(unix))]
    return meta.is_file() && inode == 0;
}

/// The dynamic library holding this function and the inode it was mapped from: the
/// `/proc/self/maps` line whose address range contains it.
fn own_library() -> Option<(PathBuf, u64)> {
    let here = own_library as fn() -> Option<(PathBuf, u64)> as usize;
    let maps = std::fs::read_to_string("/proc/self/maps").ok()?;
    library_at(&maps, here)
}

/// The path and inode of the mapping of `maps` (the `/proc/PID/maps` format) that contains
/// `address`.
fn library_at(maps: &str, address: usize) -> Option<(PathBuf, u64)> {
    maps.lines().find_map(|line| {
        let mut fields = line.split_whitespace();
        let (start, end) = fields.next()?.split_once('-')?;
        let (start, end) = (usize::from_str_radix(start, 16).ok()?, usize::from_str_radix(end, 16).ok()?);
        let inode = fields.nth(3)?.parse().ok()?;
        let path = fields.next()?;
        (start <= address && address < end && path.starts_with('/')).then(|| (PathBuf::from(path), inode))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("gam-algebra-cache-test-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        d
    }

    #[test]
    fn a_stored_expansion_is_read_back_for_the_same_key_only() {
        let d = dir("keys");
        let key = Key::at(&d, "/x/crate", "pga", "lib.so 10 1", "pub mod pga { types { A = grade 1 ; } }");
        assert_eq!(key.lookup(), None);
        key.store("pub mod pga { }\n// second line");
        assert_eq!(key.lookup().as_deref(), Some("pub mod pga { }\n// second line"));
        // another invocation of the same module: same file, different header, a miss
        let edited = Key::at(&d, "/x/crate", "pga", "lib.so 10 1", "pub mod pga { types { A = grade 2 ; } }");
        assert_eq!(edited.file, key.file);
        assert_eq!(edited.lookup(), None);
        // a rebuilt generator: a miss
        let rebuilt = Key::at(&d, "/x/crate", "pga", "lib.so 10 2", "pub mod pga { types { A = grade 1 ; } }");
        assert_eq!(rebuilt.lookup(), None);
        // a damaged entry is a miss
        let text = std::fs::read_to_string(&key.file).unwrap();
        std::fs::write(&key.file, text.replace("second", "2nd")).unwrap();
        assert_eq!(key.lookup(), None);
        std::fs::write(&key.file, &text[..text.len() - 3]).unwrap();
        assert_eq!(key.lookup(), None);
        // the edit overwrites the module's entry: the first key misses now
        edited.store("pub mod pga { struct B; }");
        assert_eq!(edited.lookup().as_deref(), Some("pub mod pga { struct B; }"));
        assert_eq!(key.lookup(), None);
        // another module or crate has its own entry
        assert_ne!(Key::at(&d, "/x/crate", "cga", "g", "i").file, key.file);
        assert_ne!(Key::at(&d, "/y/crate", "pga", "g", "i").file, key.file);
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn invocations_differing_only_in_line_breaks_have_different_headers() {
        let d = dir("lines");
        let (a, b) = (Key::at(&d, "c", "m", "g", "a\nb"), Key::at(&d, "c", "m", "g", "a\\nb"));
        assert_ne!(a.header, b.header);
        assert!(!a.header.contains('\n'));
    }

    #[cfg(unix)]
    #[test]
    fn a_directory_writable_by_others_is_not_trusted() {
        use std::os::unix::fs::PermissionsExt;
        let d = dir("trust");
        let own = std::fs::metadata(std::env::current_exe().unwrap()).unwrap();
        assert!(trusted(&d, &own), "absent: created on the first store");
        std::fs::create_dir_all(&d).unwrap();
        std::fs::set_permissions(&d, std::fs::Permissions::from_mode(0o755)).unwrap();
        assert!(trusted(&d, &own));
        std::fs::set_permissions(&d, std::fs::Permissions::from_mode(0o777)).unwrap();
        assert!(!trusted(&d, &own));
        std::fs::remove_dir_all(&d).unwrap();
        let file = d.with_extension("file");
        std::fs::write(&file, "").unwrap();
        assert!(!trusted(&file, &own), "not a directory");
        std::fs::remove_file(&file).unwrap();
    }

    #[test]
    fn the_mapping_holding_an_address_is_found() {
        let maps = "\
55d0c0a00000-55d0c0a21000 r--p 00000000 fd:01 123 /usr/bin/rustc
7f0000000000-7f0000100000 r-xp 00010000 fd:01 456 /t/debug/deps/libalgebra_macros-1.so
7f0000100000-7f0000200000 rw-p 00000000 00:00 0
7ffd00000000-7ffd00021000 rw-p 00000000 00:00 0 [stack]
";
        assert_eq!(
            library_at(maps, 0x7f0000000010),
            Some((PathBuf::from("/t/debug/deps/libalgebra_macros-1.so"), 456))
        );
        assert_eq!(library_at(maps, 0x7f0000100010), None);
        assert_eq!(library_at(maps, 0x7ffd00000010), None);
        assert_eq!(library_at(maps, 0x1000), None);
        // in this test binary, the function is in the test executable itself, mapped from the
        // file on disk
        let (path, inode) = own_library().unwrap();
        assert!(same_inode(&std::fs::metadata(&path).unwrap(), inode));
        assert!(!same_inode(&std::fs::metadata(&path).unwrap(), inode + 1));
    }
}
