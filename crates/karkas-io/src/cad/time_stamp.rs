//! The time stamp a STEP header (`FILE_NAME`'s `time_stamp`, ISO 8601) and an IGES global
//! section (fields 18 and 25, `YYYYMMDD.HHNNSS`) carry: the moment the file was written, in UTC.
//!
//! The clock is read through `web-time` (the standard clock natively, the browser's in the
//! workbench page) and converted to a calendar date by `time`. Reproducible output follows the
//! reproducible-builds convention: when the environment variable `SOURCE_DATE_EPOCH` holds a
//! whole number of seconds since 1970-01-01 UTC, that moment is written instead, so two runs
//! give the same bytes.

use time::OffsetDateTime;

/// The environment variable that fixes the written moment (seconds since the Unix epoch).
pub const SOURCE_DATE_EPOCH: &str = "SOURCE_DATE_EPOCH";

/// A moment in UTC, whole seconds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FileStamp {
    moment: OffsetDateTime,
}

impl FileStamp {
    /// `SOURCE_DATE_EPOCH` when it holds a valid moment, otherwise the clock (the Unix epoch if
    /// the clock stands before it).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas_io::cad::time_stamp::FileStamp;
    ///
    /// // The clock or SOURCE_DATE_EPOCH: either way a moment spelled like any other.
    /// let now = FileStamp::now();
    /// assert_eq!(now.iso8601().len(), FileStamp::EPOCH.iso8601().len());
    /// ```
    pub fn now() -> Self {
        Self::fixed_or_clock(std::env::var(SOURCE_DATE_EPOCH).ok().as_deref())
    }

    /// The moment `fixed` names (whole seconds since the Unix epoch, as `SOURCE_DATE_EPOCH`
    /// holds it) when it is valid, otherwise the clock.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas_io::cad::time_stamp::FileStamp;
    ///
    /// let fixed = FileStamp::fixed_or_clock(Some("86400"));
    /// assert!(fixed.iso8601().starts_with("1970-01-02"));
    /// ```
    pub fn fixed_or_clock(fixed: Option<&str>) -> Self {
        let fixed = fixed
            .and_then(|text| text.trim().parse::<i64>().ok())
            .and_then(Self::from_unix_seconds);
        fixed.unwrap_or_else(|| {
            let seconds = web_time::SystemTime::now()
                .duration_since(web_time::UNIX_EPOCH)
                .map_or(0, |elapsed| elapsed.as_secs());
            Self::from_unix_seconds(i64::try_from(seconds).unwrap_or(0)).unwrap_or(Self::EPOCH)
        })
    }

    /// 1970-01-01 00:00:00 UTC.
    pub const EPOCH: Self = Self {
        moment: OffsetDateTime::UNIX_EPOCH,
    };

    /// The moment `seconds` after 1970-01-01 UTC, or `None` outside the years 0..=9999 that
    /// both formats can spell.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas_io::cad::time_stamp::FileStamp;
    ///
    /// let stamp = FileStamp::from_unix_seconds(0).expect("the epoch is in range");
    /// assert!(stamp.iso8601().starts_with("1970-01-01"));
    /// assert!(FileStamp::from_unix_seconds(i64::MAX).is_none());
    /// ```
    pub fn from_unix_seconds(seconds: i64) -> Option<Self> {
        let moment = OffsetDateTime::from_unix_timestamp(seconds).ok()?;
        (0..=9999)
            .contains(&moment.year())
            .then_some(Self { moment })
    }

    /// ISO 8601 as STEP writes it: `2026-11-28T05:18:43`.
    pub fn iso8601(&self) -> String {
        let [year, month, day, hour, minute, second] = self.fields();
        format!("{year:04}-{month:02}-{day:02}T{hour:02}:{minute:02}:{second:02}")
    }

    /// IGES 5.3's 15-character form: `20261128.051843`.
    pub fn iges(&self) -> String {
        let [year, month, day, hour, minute, second] = self.fields();
        format!("{year:04}{month:02}{day:02}.{hour:02}{minute:02}{second:02}")
    }

    /// Year, month, day, hour, minute and second.
    fn fields(&self) -> [i32; 6] {
        let m = self.moment;
        [
            m.year(),
            i32::from(u8::from(m.month())),
            i32::from(m.day()),
            i32::from(m.hour()),
            i32::from(m.minute()),
            i32::from(m.second()),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_moments_are_spelled_as_both_formats_require() {
        // 1_000_000_000 s after the epoch is 2001-09-09 01:46:40 UTC; 951_782_400 is the leap
        // day 2000-02-29 00:00:00.
        let billennium = FileStamp::from_unix_seconds(1_000_000_000).expect("in range");
        assert_eq!(billennium.iso8601(), "2001-09-09T01:46:40");
        assert_eq!(billennium.iges(), "20010909.014640");
        let leap = FileStamp::from_unix_seconds(951_782_400).expect("in range");
        assert_eq!(leap.iso8601(), "2000-02-29T00:00:00");
        assert_eq!(FileStamp::EPOCH.iges(), "19700101.000000");
    }

    #[test]
    fn a_fixed_moment_wins_over_the_clock_only_when_valid() {
        let fixed = FileStamp::fixed_or_clock(Some(" 1000000000 "));
        assert_eq!(fixed.iso8601(), "2001-09-09T01:46:40");
        // Text that is not a moment falls back to the clock, which stands after 2026-01-01.
        for text in [
            None,
            Some("yesterday"),
            Some("1e9"),
            Some("999999999999999"),
        ] {
            let clock = FileStamp::fixed_or_clock(text);
            assert!(
                clock.iso8601().as_str() > "2026-01-01",
                "{text:?}: {}",
                clock.iso8601()
            );
        }
    }

    #[test]
    fn moments_outside_four_digit_years_are_refused() {
        assert!(FileStamp::from_unix_seconds(253_402_300_800).is_none()); // 10000-01-01
        assert!(FileStamp::from_unix_seconds(i64::MAX).is_none());
        assert!(FileStamp::from_unix_seconds(253_402_300_799).is_some()); // 9999-12-31 23:59:59
    }
}
