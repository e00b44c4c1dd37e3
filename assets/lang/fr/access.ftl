# Keyboard, sound and screen-reader access.
