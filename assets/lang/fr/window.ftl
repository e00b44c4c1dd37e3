# window
this-language = Français
