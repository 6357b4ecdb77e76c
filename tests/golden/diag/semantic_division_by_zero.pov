#declare Zero = 0;
sphere { 0, 1 / Zero }
