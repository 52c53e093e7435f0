//! Destinations: refuse a write that would clobber an input or another
//! output, and write every output only once all of them can be written.
//!
//! A command computes everything and serializes every output to memory
//! first; [`write_all`] then stages each file as a temporary file in its
//! destination directory (which checks that the directory exists and is
//! writable and that the data fits), and only when every file is staged
//! renames them over their destinations. A failure before the renames
//! leaves every destination as it was; a rename replaces the old file
//! whole, so no reader sees a half-written file. (If the renames
//! themselves fail part-way, which needs the directory to change under the
//! command, the files renamed so far stay written.) Destinations that are
//! not regular files (`/dev/null`, a terminal) are opened at staging and
//! written at the end. A regular destination keeps its permissions and
//! must be writable, as for a direct write.

use crate::errors::usage;
use std::fs::{self, File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use umbra::UmbraError;

/// The destinations of a command that writes a result: `-o OUT` and
/// `--report R.json` (flattened into the command's arguments).
#[derive(clap::Args, Debug)]
pub struct OutputArgs {
    /// The output file (its extension picks the format).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Write a JSON report (counts, validity, epsilon, timings) here.
    #[arg(long)]
    pub report: Option<PathBuf>,
    /// STL and PLY output as text (ASCII; every f64 kept bit for bit)
    /// instead of binary (STL binary stores f32).
    #[arg(long)]
    pub ascii: bool,
}

impl OutputArgs {
    /// The mesh writer's options these arguments ask for.
    pub fn mesh_options(&self) -> umbra::MeshWriteOptions {
        umbra::MeshWriteOptions { text: self.ascii }
    }
}

impl OutputArgs {
    /// Refuses (usage error) an output or report that is one of `reads`
    /// (`(role, path)`) or that are the same file.
    pub fn refuse_overlaps(&self, reads: &[(&str, &Path)]) -> anyhow::Result<()> {
        let mut writes = vec![("the output", self.output.as_path())];
        if let Some(r) = &self.report {
            writes.push(("the report", r.as_path()));
        }
        refuse_overlaps(&writes, reads)
    }

    /// Writes the output and, if asked, the report as JSON: both or
    /// neither ([`write_all`]).
    pub fn write<R: serde::Serialize>(&self, output: &[u8], report: &R) -> anyhow::Result<()> {
        match &self.report {
            Some(path) => write_all(&[(&self.output, output), (path, &report_json(report)?)])?,
            None => write_all(&[(&self.output, output)])?,
        }
        Ok(())
    }
}

/// The identity of a path for comparisons: canonical when the file exists
/// (symbolic links and `..` resolved), else its canonical directory joined
/// with its name, else the absolute path as written.
fn identity(path: &Path) -> PathBuf {
    if let Ok(canonical) = fs::canonicalize(path) {
        return canonical;
    }
    let abs = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    if let (Some(dir), Some(name)) = (abs.parent(), abs.file_name()) {
        if let Ok(dir) = fs::canonicalize(dir) {
            return dir.join(name);
        }
    }
    abs
}

/// `true` when both paths exist and are the same file (hard links too).
#[cfg(unix)]
fn same_file(a: &Path, b: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (fs::metadata(a), fs::metadata(b)) {
        (Ok(x), Ok(y)) => x.dev() == y.dev() && x.ino() == y.ino(),
        _ => false,
    }
}

/// `true` when both paths exist and are the same file (by canonical path
/// only on this platform).
#[cfg(not(unix))]
fn same_file(_: &Path, _: &Path) -> bool {
    false
}

/// Refuses (usage error, exit 2) any destination in `writes` that is also
/// a file of `reads` or another destination. Each entry is `(role, path)`,
/// the role as a message names it (`"the output"`, `"operand A"`).
pub fn refuse_overlaps(writes: &[(&str, &Path)], reads: &[(&str, &Path)]) -> anyhow::Result<()> {
    let reads: Vec<(&str, &Path, PathBuf)> = reads
        .iter()
        .map(|&(role, p)| (role, p, identity(p)))
        .collect();
    let writes: Vec<(&str, &Path, PathBuf)> = writes
        .iter()
        .map(|&(role, p)| (role, p, identity(p)))
        .collect();
    for (i, (role, path, id)) in writes.iter().enumerate() {
        let clash = reads
            .iter()
            .chain(&writes[..i])
            .find(|(_, other_path, other)| other == id || same_file(path, other_path));
        if let Some((other_role, _, _)) = clash {
            return Err(usage(format!(
                "{}: {role} would overwrite {other_role} (the same file); nothing was written",
                path.display()
            )));
        }
    }
    Ok(())
}

/// A file staged for writing.
enum Staged {
    /// A temporary file beside the destination, renamed over it on commit.
    Temp {
        dest: PathBuf,
        target: PathBuf,
        temp: PathBuf,
    },
    /// A destination that is not a regular file, opened for writing.
    Direct {
        dest: PathBuf,
        file: File,
        bytes: Vec<u8>,
    },
}

/// The write error for the destination `dest` (as the user named it).
fn write_error(dest: &Path, source: std::io::Error) -> UmbraError {
    UmbraError::Io {
        file: dest.display().to_string(),
        action: "write",
        source,
    }
}

static TEMP_COUNTER: AtomicUsize = AtomicUsize::new(0);

/// Stages `bytes` for `dest`.
fn stage(dest: &Path, bytes: &[u8]) -> Result<Staged, UmbraError> {
    // Write through a symbolic link to the file it points at.
    let target = fs::canonicalize(dest).unwrap_or_else(|_| dest.to_path_buf());
    let existing = fs::metadata(&target).ok();
    if existing.as_ref().is_some_and(|m| !m.is_file()) {
        let file = OpenOptions::new()
            .write(true)
            .truncate(true)
            .open(&target)
            .map_err(|e| write_error(dest, e))?;
        return Ok(Staged::Direct {
            dest: dest.to_path_buf(),
            file,
            bytes: bytes.to_vec(),
        });
    }
    if existing.is_some() {
        // The file must be writable as it stands (a read-only file is
        // refused, as a direct write would be), though it is replaced.
        OpenOptions::new()
            .write(true)
            .open(&target)
            .map_err(|e| write_error(dest, e))?;
    }
    let name = target
        .file_name()
        .ok_or_else(|| {
            write_error(
                dest,
                std::io::Error::new(std::io::ErrorKind::InvalidInput, "not a file name"),
            )
        })?
        .to_string_lossy()
        .into_owned();
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let temp = dir.join(format!(
        ".{name}.umbra-{}-{}.tmp",
        std::process::id(),
        TEMP_COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    let written = (|| {
        let mut file = OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&temp)?;
        file.write_all(bytes)?;
        file.sync_all()?;
        if let Some(meta) = &existing {
            fs::set_permissions(&temp, meta.permissions())?;
        }
        Ok(())
    })();
    match written {
        Ok(()) => Ok(Staged::Temp {
            dest: dest.to_path_buf(),
            target,
            temp,
        }),
        Err(e) => {
            let _ = fs::remove_file(&temp);
            Err(write_error(dest, e))
        }
    }
}

impl Staged {
    fn commit(self) -> Result<(), UmbraError> {
        match self {
            Staged::Temp { dest, target, temp } => fs::rename(&temp, &target).map_err(|e| {
                let _ = fs::remove_file(&temp);
                write_error(&dest, e)
            }),
            Staged::Direct {
                dest,
                mut file,
                bytes,
            } => file
                .write_all(&bytes)
                .and_then(|()| file.flush())
                .map_err(|e| write_error(&dest, e)),
        }
    }

    fn discard(self) {
        if let Staged::Temp { temp, .. } = self {
            let _ = fs::remove_file(temp);
        }
    }
}

/// Writes every `(destination, contents)` pair, or none when any cannot
/// be staged (see the module docs). The error names the destination.
pub fn write_all(files: &[(&Path, &[u8])]) -> Result<(), UmbraError> {
    let mut staged = Vec::with_capacity(files.len());
    for &(dest, bytes) in files {
        match stage(dest, bytes) {
            Ok(s) => staged.push(s),
            Err(e) => {
                staged.into_iter().for_each(Staged::discard);
                return Err(e);
            }
        }
    }
    let mut staged = staged.into_iter();
    while let Some(s) = staged.next() {
        if let Err(e) = s.commit() {
            staged.for_each(Staged::discard);
            return Err(e);
        }
    }
    Ok(())
}

/// Serializes a report as pretty JSON with a final newline.
pub fn report_json<T: serde::Serialize>(report: &T) -> anyhow::Result<Vec<u8>> {
    let mut bytes = serde_json::to_vec_pretty(report).map_err(|e| {
        anyhow::anyhow!(
            "internal error (this is a bug, please report it): cannot serialise the report: {e}"
        )
    })?;
    bytes.push(b'\n');
    Ok(bytes)
}
