//! The window's words, in the language the person reads: every text a
//! person reads in the window comes from the Fluent files under
//! `assets/lang/<language>/` (embedded in the binary), through [`tr!`].
//!
//! A message missing from a language falls back to English, message by
//! message. The language is the thread's (the window has one thread; each
//! test thread starts in English): [`set_language`] changes it, and the
//! numbers follow it ([`decimal_comma`]: "2,50" in es, fr, de, pt-BR, whose
//! vectors then read "(2,50; 0,00)"). `qps` is a pseudo-language for
//! checking the layout: English with every letter accented, 40 % longer,
//! in brackets.
//!
//! The command line, its errors, the lab, the CSV and scene files and the
//! state dump stay English with a decimal point.

mod pseudo;

use fluent_bundle::{FluentArgs, FluentBundle, FluentResource, FluentValue};
use std::cell::RefCell;
use std::rc::Rc;

/// A language the window speaks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Lang {
    #[default]
    En,
    Es,
    Fr,
    De,
    PtBr,
    /// The pseudo-language for layout checks.
    Qps,
}

impl Lang {
    /// The languages offered in the View menu, in its order.
    pub const SHIPPED: [Lang; 5] = [Lang::En, Lang::Es, Lang::Fr, Lang::De, Lang::PtBr];

    /// Its BCP 47 tag, as `--lang` takes it and the settings file keeps it.
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Es => "es",
            Lang::Fr => "fr",
            Lang::De => "de",
            Lang::PtBr => "pt-BR",
            Lang::Qps => "qps",
        }
    }

    /// The language a tag names: `--lang`'s codes, and the locales of the
    /// system (`es_ES.UTF-8`, `de-AT`, `pt_PT`) and the browser (`fr-CA`);
    /// `None` for a language Impulse does not speak (or `C`, `POSIX`).
    pub fn from_tag(tag: &str) -> Option<Lang> {
        let tag = tag
            .split(['.', '@'])
            .next()
            .unwrap_or("")
            .to_ascii_lowercase();
        let primary = tag.split(['-', '_']).next().unwrap_or("");
        Some(match primary {
            "en" => Lang::En,
            "es" => Lang::Es,
            "fr" => Lang::Fr,
            "de" => Lang::De,
            "pt" => Lang::PtBr,
            "qps" => Lang::Qps,
            _ => return None,
        })
    }

    /// Whether numbers in it take a decimal comma.
    pub fn decimal_comma(self) -> bool {
        matches!(self, Lang::Es | Lang::Fr | Lang::De | Lang::PtBr)
    }

    /// The folder of its Fluent files (the pseudo-language reads English's).
    fn folder(self) -> &'static str {
        match self {
            Lang::Qps => "en",
            other => other.code(),
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
/// The language the system's locale asks for (`LC_ALL`, `LC_MESSAGES`,
/// `LANG`, `LANGUAGE`, the first one set), if Impulse speaks it.
pub fn system_language() -> Option<Lang> {
    for name in ["LC_ALL", "LC_MESSAGES", "LANG", "LANGUAGE"] {
        if let Ok(value) = std::env::var(name) {
            if value.is_empty() {
                continue;
            }
            // LANGUAGE is a list ("de:en"); a set variable decides.
            return value.split(':').find_map(Lang::from_tag);
        }
    }
    None
}

/// The Fluent files, by folder: embedded, so the binary and the browser
/// build carry them.
pub const FILES: &[(&str, &str, &str)] = &[
    (
        "en",
        "window.ftl",
        include_str!("../../../assets/lang/en/window.ftl"),
    ),
    (
        "en",
        "keys.ftl",
        include_str!("../../../assets/lang/en/keys.ftl"),
    ),
    (
        "en",
        "messages.ftl",
        include_str!("../../../assets/lang/en/messages.ftl"),
    ),
    (
        "en",
        "access.ftl",
        include_str!("../../../assets/lang/en/access.ftl"),
    ),
    (
        "es",
        "window.ftl",
        include_str!("../../../assets/lang/es/window.ftl"),
    ),
    (
        "es",
        "keys.ftl",
        include_str!("../../../assets/lang/es/keys.ftl"),
    ),
    (
        "es",
        "messages.ftl",
        include_str!("../../../assets/lang/es/messages.ftl"),
    ),
    (
        "es",
        "access.ftl",
        include_str!("../../../assets/lang/es/access.ftl"),
    ),
    (
        "fr",
        "window.ftl",
        include_str!("../../../assets/lang/fr/window.ftl"),
    ),
    (
        "fr",
        "keys.ftl",
        include_str!("../../../assets/lang/fr/keys.ftl"),
    ),
    (
        "fr",
        "messages.ftl",
        include_str!("../../../assets/lang/fr/messages.ftl"),
    ),
    (
        "fr",
        "access.ftl",
        include_str!("../../../assets/lang/fr/access.ftl"),
    ),
    (
        "de",
        "window.ftl",
        include_str!("../../../assets/lang/de/window.ftl"),
    ),
    (
        "de",
        "keys.ftl",
        include_str!("../../../assets/lang/de/keys.ftl"),
    ),
    (
        "de",
        "messages.ftl",
        include_str!("../../../assets/lang/de/messages.ftl"),
    ),
    (
        "de",
        "access.ftl",
        include_str!("../../../assets/lang/de/access.ftl"),
    ),
    (
        "pt-BR",
        "window.ftl",
        include_str!("../../../assets/lang/pt-BR/window.ftl"),
    ),
    (
        "pt-BR",
        "keys.ftl",
        include_str!("../../../assets/lang/pt-BR/keys.ftl"),
    ),
    (
        "pt-BR",
        "messages.ftl",
        include_str!("../../../assets/lang/pt-BR/messages.ftl"),
    ),
    (
        "pt-BR",
        "access.ftl",
        include_str!("../../../assets/lang/pt-BR/access.ftl"),
    ),
];

type Bundle = FluentBundle<FluentResource>;

/// One language's messages, with English behind them.
pub struct Words {
    lang: Lang,
    bundle: Bundle,
    english: Option<Bundle>,
}

fn bundle(lang: Lang) -> Bundle {
    let id: unic_langid::LanguageIdentifier = match lang {
        Lang::Qps => "en".parse(),
        other => other.code().parse(),
    }
    .expect("the language tags are valid");
    let mut bundle = FluentBundle::new(vec![id]);
    // No Unicode isolation marks around placeables: the fonts draw them as
    // boxes, and every text here runs left to right.
    bundle.set_use_isolating(false);
    if lang == Lang::Qps {
        bundle.set_transform(Some(pseudo::accent));
    }
    for (folder, name, text) in FILES.iter().filter(|(f, _, _)| *f == lang.folder()) {
        let resource = FluentResource::try_new(text.to_string())
            .unwrap_or_else(|(_, errors)| panic!("{folder}/{name}: {errors:?}"));
        bundle
            .add_resource(resource)
            .unwrap_or_else(|errors| panic!("{folder}/{name}: {errors:?}"));
    }
    bundle
}

impl Words {
    pub fn new(lang: Lang) -> Self {
        Words {
            lang,
            bundle: bundle(lang),
            english: (lang.folder() != "en").then(|| bundle(Lang::En)),
        }
    }

    /// Whether `id` ("message" or "message.attribute") exists in this
    /// language itself (not through the fallback).
    #[cfg(test)]
    pub fn has(&self, id: &str) -> bool {
        lookup(&self.bundle, id, None).is_some()
    }

    /// The message `id` with `args`, from this language or else English;
    /// the id itself if neither has it (a test keeps that from happening).
    pub fn get(&self, id: &str, args: &[(&str, Arg)]) -> String {
        let mut fluent = FluentArgs::new();
        for (name, value) in args {
            fluent.set(
                *name,
                match value {
                    Arg::Text(t) => FluentValue::from(t.clone()),
                    Arg::Count(n) => FluentValue::from(*n),
                },
            );
        }
        let args = (!args.is_empty()).then_some(&fluent);
        if let Some(text) = lookup(&self.bundle, id, args) {
            return if self.lang == Lang::Qps {
                pseudo::lengthen(&text)
            } else {
                text
            };
        }
        self.english
            .as_ref()
            .and_then(|english| lookup(english, id, args))
            .unwrap_or_else(|| id.to_string())
    }
}

/// `id` formatted from `bundle`, if it has it.
fn lookup(bundle: &Bundle, id: &str, args: Option<&FluentArgs>) -> Option<String> {
    let (message, attribute) = match id.split_once('.') {
        Some((m, a)) => (m, Some(a)),
        None => (id, None),
    };
    let message = bundle.get_message(message)?;
    let pattern = match attribute {
        Some(a) => message.get_attribute(a)?.value(),
        None => message.value()?,
    };
    let mut errors = Vec::new();
    let text = bundle.format_pattern(pattern, args, &mut errors);
    debug_assert!(errors.is_empty(), "{id}: {errors:?}");
    Some(text.into_owned())
}

/// A value put into a message: a text (numbers formatted by
/// [`crate::app::numbers`] first, so they follow the language) or a count
/// (which picks the plural form).
#[derive(Clone, Debug, PartialEq)]
pub enum Arg {
    Text(String),
    Count(i64),
}

impl From<String> for Arg {
    fn from(t: String) -> Self {
        Arg::Text(t)
    }
}
impl From<&String> for Arg {
    fn from(t: &String) -> Self {
        Arg::Text(t.clone())
    }
}
impl From<&str> for Arg {
    fn from(t: &str) -> Self {
        Arg::Text(t.to_string())
    }
}
macro_rules! counts {
    ($($t:ty),*) => {$(
        impl From<$t> for Arg {
            fn from(n: $t) -> Self {
                Arg::Count(i64::try_from(n).unwrap_or(i64::MAX))
            }
        }
    )*};
}
counts!(usize, u32, u64, u8, i32, i64);

thread_local! {
    static CURRENT: RefCell<Rc<Words>> = RefCell::new(Rc::new(Words::new(Lang::En)));
}

/// A language's name in itself ("Deutsch"), as the language lists show it:
/// its `this-language` message, read from the file's text (no bundle is
/// built for a language only named).
pub fn native_name(lang: Lang) -> String {
    let own = FILES
        .iter()
        .filter(|(folder, _, _)| *folder == lang.folder())
        .flat_map(|(_, _, text)| text.lines())
        .find_map(|line| line.strip_prefix("this-language = "))
        .unwrap_or(lang.code())
        .trim();
    match lang {
        Lang::Qps => pseudo::lengthen(&pseudo::accent(own)),
        _ => own.to_string(),
    }
}

/// Speaks `lang` from now on (on this thread).
pub fn set_language(lang: Lang) {
    CURRENT.with(|c| {
        if c.borrow().lang != lang {
            *c.borrow_mut() = Rc::new(Words::new(lang));
        }
    });
}

/// The language spoken now.
pub fn language() -> Lang {
    CURRENT.with(|c| c.borrow().lang)
}

/// Whether numbers now take a decimal comma.
pub fn decimal_comma() -> bool {
    language().decimal_comma()
}

/// The message `id` in the current language (use [`tr!`]).
pub fn text(id: &str, args: &[(&str, Arg)]) -> String {
    let words = CURRENT.with(|c| Rc::clone(&c.borrow()));
    words.get(id, args)
}

/// The message `id` in the current language, with named values:
/// `tr!("discs-count", count = n)`.
macro_rules! tr {
    ($id:expr) => {
        $crate::app::lang::text($id, &[])
    };
    ($id:expr, $($name:ident = $value:expr),+ $(,)?) => {
        $crate::app::lang::text(
            $id,
            &[$((stringify!($name), $crate::app::lang::Arg::from($value))),+],
        )
    };
}
pub(crate) use tr;

#[cfg(test)]
mod tests;
