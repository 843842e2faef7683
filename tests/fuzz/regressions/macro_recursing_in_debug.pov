#macro F(N)#debug F(N + 1) #end
F(0)