#declare Quality = 11;
#if (Quality > 10)
  #error concat("Quality ", str(Quality, 0, 0), " is out of range")
#end
sphere { 0, 1 }
