//! A file writer that has the disk write its bytes in the background as they come.
//!
//! [`crate::write::write_atomic`] syncs its temporary file before renaming it over the
//! destination, so that a crash of the machine cannot leave a renamed file without its
//! bytes. The operating system holds written bytes in memory until asked, so for a large
//! output that final sync waited for the whole file to reach the disk after the last byte
//! was produced: 0.45 s of the 2.4 s `karkas inspect` took to write a 190 MB report.
//! [`Writeback`] asks for the disk write every [`WRITEBACK_BYTES`], on a thread of its own,
//! so the disk works while the rest is produced and the final sync waits for the tail only.
//!
//! The standard library has no asynchronous "start writing back" call (Linux's
//! `sync_file_range` needs `unsafe`, which karkas forbids), so the background thread calls
//! [`File::sync_data`] on a second handle of the same file. An error it meets is kept and
//! returned by [`Writeback::finish`]: a sync that fails reports the failure once, so it
//! must not be lost.

use std::fs::File;
use std::io::{self, Write};
use std::sync::mpsc::{self, SyncSender, TrySendError};
use std::thread::JoinHandle;

/// Bytes written between two requests for the disk write. Smaller outputs never start the
/// background thread.
pub(crate) const WRITEBACK_BYTES: u64 = 16 << 20;

/// A [`File`] whose written bytes are synced to disk in the background, each
/// [`WRITEBACK_BYTES`].
pub(crate) struct Writeback {
    file: File,
    /// Bytes written since the last request.
    pending: u64,
    /// The background thread, once the first request was made, and its wake-up channel.
    syncer: Option<(SyncSender<()>, JoinHandle<io::Result<()>>)>,
}

impl Writeback {
    pub(crate) fn new(file: File) -> Self {
        Self {
            file,
            pending: 0,
            syncer: None,
        }
    }

    /// Asks the background thread to sync what was written; a request while it is still
    /// syncing is dropped, since its next sync covers these bytes too.
    fn request(&mut self) -> io::Result<()> {
        self.pending = 0;
        if self.syncer.is_none() {
            let handle = self.file.try_clone()?;
            let (wake, woken) = mpsc::sync_channel::<()>(1);
            let thread = std::thread::Builder::new()
                .name("karkas-writeback".into())
                .spawn(move || {
                    while woken.recv().is_ok() {
                        handle.sync_data()?;
                    }
                    Ok(())
                })?;
            self.syncer = Some((wake, thread));
        }
        if let Some((wake, _)) = &self.syncer {
            match wake.try_send(()) {
                Ok(()) | Err(TrySendError::Full(())) => {}
                // The thread stopped on an error: `finish` returns it.
                Err(TrySendError::Disconnected(())) => {}
            }
        }
        Ok(())
    }

    /// Stops the background thread and syncs the whole file, data and metadata: the first
    /// error of any sync, or `Ok` with the file on disk.
    pub(crate) fn finish(mut self) -> io::Result<File> {
        if let Some((wake, thread)) = self.syncer.take() {
            drop(wake);
            thread
                .join()
                .map_err(|_| io::Error::other("the background sync stopped"))??;
        }
        self.file.sync_all()?;
        Ok(self.file)
    }
}

impl Write for Writeback {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let written = self.file.write(buf)?;
        self.pending += written as u64;
        if self.pending >= WRITEBACK_BYTES {
            self.request()?;
        }
        Ok(written)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.file.flush()
    }
}
