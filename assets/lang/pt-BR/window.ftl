# window
this-language = Português (Brasil)
