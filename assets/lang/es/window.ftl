# window
this-language = Español
