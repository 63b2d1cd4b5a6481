local = = = {{{{ ]] 'unterminated
