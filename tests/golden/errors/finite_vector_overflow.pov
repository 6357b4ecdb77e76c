// A vector product that overflows in one component.
#declare V = <1, 2, 1e308> * <1, 1, 10>;
