//! Error text for the command-line tools: an error and its causes folded onto one line.

/// An error and its chain of causes (`source()`) on one line, `outer: cause: …`, skipping a
/// cause whose text the line already holds (many error types print their source inside their
/// own message, and context layers often repeat it) and folding line breaks into spaces.
pub fn error_line(error: &(dyn std::error::Error + 'static)) -> String {
    let mut line = String::new();
    let mut next = Some(error);
    while let Some(e) = next {
        let msg = e.to_string();
        if !msg.is_empty() && !line.contains(&msg) {
            if !line.is_empty() {
                line.push_str(": ");
            }
            line.push_str(&msg);
        }
        next = e.source();
    }
    line.replace('\n', " ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug)]
    struct E(&'static str, Option<Box<E>>);
    impl std::fmt::Display for E {
        fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            f.write_str(self.0)
        }
    }
    impl std::error::Error for E {
        fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
            self.1.as_deref().map(|e| e as _)
        }
    }

    #[test]
    fn causes_are_joined_once_on_one_line() {
        let io = E("No such file (os error 2)", None);
        let own = E(
            "cannot read a.toml: No such file (os error 2)",
            Some(Box::new(io)),
        );
        let ctx = E("aircraft", Some(Box::new(own)));
        assert_eq!(
            error_line(&ctx),
            "aircraft: cannot read a.toml: No such file (os error 2)"
        );
        let folded = E("two\nlines", Some(Box::new(E("cause", None))));
        assert_eq!(error_line(&folded), "two lines: cause");
    }
}
