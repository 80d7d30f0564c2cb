//! Thin proc-macro front end for the `algebra!` DSL (arrives with the code-generation issue).
