" rts scene files.
autocmd BufRead,BufNewFile *.rts setfiletype rts
