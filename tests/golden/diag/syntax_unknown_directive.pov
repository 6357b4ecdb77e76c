#inlcude "colors.inc"
