# window
this-language = Deutsch
