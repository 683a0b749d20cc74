#macro M(a) #if (a > 0) M(a - 1) #end #end
object { M(3) }
#declare S = sphere { 0, 1 }
#switch (1) #case (1) object { S } #break #else #end
camera { right -x*image_width/image_height }
