-- security: terminal escape codes in a message are shown, not sent to the terminal
error("\27[2J\27]0;owned\7 cleared your screen")
